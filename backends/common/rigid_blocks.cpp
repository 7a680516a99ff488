#include "rigid_blocks.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "error.hpp"
#include "geometry/hexahedron.hpp"
#include "geometry/spring_bed.hpp"

namespace cairn {

namespace {

// area of a planar quadrilateral face
double face_area(const Corners& c, int face) {
    const auto& f = kFaceCorners[face];
    return 0.5 * (c[f[2]] - c[f[0]]).cross(c[f[3]] - c[f[1]]).norm();
}

// outward unit normal of a face (from its diagonals; away from the block's centroid)
Vec3 face_normal(const Corners& c, int face, const Vec3& centroid) {
    const auto& f = kFaceCorners[face];
    Vec3 n = (c[f[2]] - c[f[0]]).cross(c[f[3]] - c[f[1]]).normalized();
    Vec3 mid = 0.25 * (c[f[0]] + c[f[1]] + c[f[2]] + c[f[3]]);
    return n.dot(mid - centroid) < 0 ? Vec3(-n) : n;
}

// true when the corners are an axis-aligned box centred on `centre`
bool axis_aligned_box(const Corners& c, Vec3& centre, Vec3& half) {
    centre = Vec3::Zero();
    for (const auto& p : c) centre += p / 8.0;
    half = (c[6] - c[0]).cwiseAbs() / 2.0;
    double scale = half.norm();
    for (int i = 0; i < 8; ++i) {
        Vec3 expect(centre.x() + half.x() * kCornerSigns[i][0], centre.y() + half.y() * kCornerSigns[i][1],
                    centre.z() + half.z() * kCornerSigns[i][2]);
        if ((c[i] - expect).norm() > 1e-9 * scale) return false;
    }
    return true;
}

}  // namespace

std::vector<RigidBlock> rigid_blocks(const Scene& scene, const std::string& backend) {
    std::vector<RigidBlock> out;
    out.reserve(scene.blocks.size());
    for (size_t i = 0; i < scene.blocks.size(); ++i) {
        const BlockDef& d = scene.blocks[i];
        if (d.model == BlockModel::deformable && !d.fixed)
            throw Error("backend " + backend + " cannot represent deformable block '" + d.name +
                        "'; run with --model rigid or use the dem backend");
        if (d.material < 0 || d.material >= static_cast<int>(scene.materials.size()))
            throw Error("block '" + d.name + "': material index " + std::to_string(d.material) +
                        " is out of range");
        RigidBlock b;
        b.index = static_cast<int>(i);
        b.name = d.name;
        b.fixed = d.fixed;
        b.corners = d.corners;
        MassProperties mp = mass_properties(d.corners, scene.materials[d.material].density);
        b.mass = mp.mass;
        b.com = mp.centre;
        b.inertia = mp.inertia;
        Vec3 centre;
        b.is_box = axis_aligned_box(d.corners, centre, b.half_extents);
        if (b.is_box) {
            // a homogeneous box: principal axes are the block axes
            b.principal.setIdentity();
            b.moments = mp.inertia.diagonal();
        } else {
            Eigen::SelfAdjointEigenSolver<Mat3> eig(mp.inertia);
            b.principal = eig.eigenvectors();
            if (b.principal.determinant() < 0) b.principal.col(2) *= -1.0;
            b.moments = eig.eigenvalues();
        }
        Vec3 centroid = Vec3::Zero();
        for (const Vec3& p : d.corners) centroid += p / 8.0;
        for (int f = 0; f < 6; ++f) {
            b.face_areas[f] = face_area(d.corners, f);
            b.face_normals[f] = face_normal(d.corners, f, centroid);
        }
        b.orientation = d.orientation.normalized();
        b.com_world = d.position + b.orientation * b.com;
        out.push_back(b);
    }
    return out;
}

Vec3 block_point_world(const RigidBlock& b, const Vec3& com_world, const Quat& q, const Vec3& point) {
    return com_world + q * (point - b.com);
}

double kinetic_energy(const RigidBlock& b, const Quat& q, const Vec3& v, const Vec3& w) {
    Mat3 r = q.toRotationMatrix();
    Vec3 wb = r.transpose() * w;
    return 0.5 * b.mass * v.squaredNorm() + 0.5 * wb.dot(b.inertia * wb);
}

double potential_energy(const RigidBlock& b, const Vec3& gravity, const Vec3& com_world) {
    return -b.mass * gravity.dot(com_world);
}

double bearing_area(const RigidBlock& b, const Quat& q, const Vec3& out) {
    const Vec3 local = q.conjugate() * out;
    double best = -2.0;
    for (const Vec3& n : b.face_normals) best = std::max(best, n.dot(local));
    double area = 0.0;
    for (int f = 0; f < 6; ++f)
        if (b.face_normals[f].dot(local) >= best - 1e-9 && (area == 0.0 || b.face_areas[f] < area))
            area = b.face_areas[f];
    return area;
}

double matched_spring_omega(const Scene& scene, const std::vector<RigidBlock>& blocks) {
    std::vector<double> w2;
    for (const RigidBlock& b : blocks) {
        if (b.fixed) continue;
        const Mat3 r = b.orientation.toRotationMatrix();
        const Mat3 inertia = r * b.inertia * r.transpose();
        double most = 0.0;
        for (size_t f = 0; f < 6; ++f) {
            std::vector<BedSpring> springs;
            for (int k : kFaceCorners[f])
                springs.push_back(
                    {block_point_world(b, b.com_world, b.orientation, b.corners[size_t(k)]), 0.25 * b.face_areas[f]});
            most = std::max(most, spring_bed_omega2(springs, b.orientation * b.face_normals[f], scene.contact.kn,
                                                    scene.contact.ks, b.com_world, b.mass, inertia));
        }
        w2.push_back(most);
    }
    if (w2.empty()) return 0.0;
    std::sort(w2.rbegin(), w2.rend());
    return std::sqrt(w2.size() > 1 ? w2[0] + w2[1] : w2[0]);
}

PointSpring matched_point_spring(const Scene& scene, const RigidBlock& a, const Quat& qa, const RigidBlock& b,
                                 const Quat& qb, const Vec3& n, int points) {
    double area = std::min(bearing_area(a, qa, n), bearing_area(b, qb, -n));
    double k = scene.contact.kn * area;
    double m = a.mass * b.mass / (a.mass + b.mass);
    if (a.fixed) m = b.mass;
    if (b.fixed) m = a.mass;
    double c = 0.0;
    switch (scene.contact.damping_rule) {
        case ContactDampingRule::none: break;
        case ContactDampingRule::ratio: c = 2.0 * scene.contact.damping * std::sqrt(k * m); break;
        case ContactDampingRule::time: c = scene.contact.damping * k; break;
    }
    return {k / points, c / points};
}

void add_block_state(Sample& sample, const RigidBlock& b, const BlockState& st, const Vec3& gravity) {
    sample.energy.kinetic += kinetic_energy(b, st.orientation, st.velocity, st.angular_velocity);
    sample.energy.potential += potential_energy(b, gravity, st.position);
    sample.blocks.push_back(st);
}

std::vector<std::string> rigid_engine_notes(const Scene& scene) {
    std::vector<std::string> n;
    if (scene.contact.ks > 0) n.push_back("shear stiffness ks: ignored (velocity-level friction)");
    if (scene.damping.beta > 0) n.push_back("stiffness-proportional damping: beta ignored (rigid bodies)");
    n.push_back("energy: contact energy 1/2 k d^2 per contact point in matched mode, 0 in rigid mode; "
                "dissipated energy not computed (reported 0)");
    return n;
}

}  // namespace cairn
