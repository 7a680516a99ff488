#include "mujoco_collision.hpp"

#include <mutex>

#include "hexahedron_contact.hpp"

namespace cairn {

namespace {

thread_local const MujocoHexahedra* g_current = nullptr;
mjfCollision g_box_mesh = nullptr;    // MuJoCo's own functions, for other models
mjfCollision g_mesh_mesh = nullptr;
mjfCollision g_box_box = nullptr;

// world corners of the block behind geom g: free blocks from their body frame (block axes at the
// centre of mass; a mesh geom's own frame is moved by MuJoCo's compiler), fixed ones as built
Corners corners(const mjModel* m, const mjData* d, const RigidBlock& b, int g) {
    Corners w;
    const int body = m->geom_bodyid[g];
    for (int i = 0; i < 8; ++i) {
        if (body == 0) {
            w[i] = block_point_world(b, b.com_world, b.orientation, b.corners[i]);
            continue;
        }
        const mjtNum* x = d->xpos + 3 * body;
        const mjtNum* r = d->xmat + 9 * body;
        const Vec3 local = b.corners[i] - b.com;
        for (int k = 0; k < 3; ++k) w[i][k] = x[k] + r[3 * k] * local[0] + r[3 * k + 1] * local[1] + r[3 * k + 2] * local[2];
    }
    return w;
}

int collide(const mjModel* m, const mjData* d, mjContact* con, int g1, int g2, mjtNum margin) {
    const MujocoHexahedra* h = g_current;
    const bool mesh_mesh = m->geom_type[g1] == mjGEOM_MESH && m->geom_type[g2] == mjGEOM_MESH;
    const bool box_box = m->geom_type[g1] == mjGEOM_BOX && m->geom_type[g2] == mjGEOM_BOX;
    mjfCollision own = mesh_mesh ? g_mesh_mesh : box_box ? g_box_box : g_box_mesh;
    if (!h || h->model != m || !h->geom_block[g1] || !h->geom_block[g2])
        return own(m, d, con, g1, g2, margin);
    auto points = hexahedron_contacts(corners(m, d, *h->geom_block[g1], g1), corners(m, d, *h->geom_block[g2], g2), 4);
    int n = 0;
    for (const HexContact& p : points) {
        mjContact& c = con[n++];
        c.dist = -p.depth * (box_box ? h->box_depth_scale : 1.0);
        // MuJoCo's normal points from geom 1 to geom 2; cairn's pushes geom 1 away from geom 2
        Vec3 normal = -p.normal;
        Vec3 t1 = normal.unitOrthogonal();
        Vec3 t2 = normal.cross(t1);
        for (int k = 0; k < 3; ++k) {
            c.pos[k] = p.position[k];
            c.frame[k] = normal[k];
            c.frame[3 + k] = t1[k];
            c.frame[6 + k] = t2[k];
        }
    }
    return n;
}

}  // namespace

void install_hexahedron_collider() {
    static std::once_flag once;
    std::call_once(once, [] {
        g_box_mesh = mjCOLLISIONFUNC[mjGEOM_BOX][mjGEOM_MESH];
        g_mesh_mesh = mjCOLLISIONFUNC[mjGEOM_MESH][mjGEOM_MESH];
        g_box_box = mjCOLLISIONFUNC[mjGEOM_BOX][mjGEOM_BOX];
        mjCOLLISIONFUNC[mjGEOM_BOX][mjGEOM_BOX] = &collide;
        mjCOLLISIONFUNC[mjGEOM_BOX][mjGEOM_MESH] = &collide;
        mjCOLLISIONFUNC[mjGEOM_MESH][mjGEOM_MESH] = &collide;
    });
}

CurrentHexahedra::CurrentHexahedra(const MujocoHexahedra* h) : previous_(g_current) { g_current = h; }

CurrentHexahedra::~CurrentHexahedra() { g_current = previous_; }

}  // namespace cairn
