#include "output/contacts_csv.hpp"

#include <cstdio>
#include <stdexcept>

#include "output/number_format.hpp"

namespace cairn {

std::vector<std::string> contact_columns() {
    return {"t [s]",  "block_a", "block_b",          "x [m]",       "y [m]",       "z [m]",      "nx [-]",
            "ny [-]", "nz [-]",  "normal_force [N]", "shear_x [N]", "shear_y [N]", "shear_z [N]"};
}

std::string contact_rows(const Scene& scene, double t, const std::vector<ContactPoint>& points) {
    auto name = [&](int b) { return b >= 0 && size_t(b) < scene.blocks.size() ? scene.blocks[size_t(b)].name : "?"; };
    std::string out;
    auto put = [&](double x) { append_exact(out, x, ','); };
    for (const ContactPoint& p : points) {
        append_exact(out, t);
        out += "," + name(p.block_a) + "," + name(p.block_b);
        for (const Vec3* v : {&p.position, &p.normal}) put(v->x()), put(v->y()), put(v->z());
        put(p.normal_force.dot(p.normal));
        put(p.shear_force.x()), put(p.shear_force.y()), put(p.shear_force.z());
        out += '\n';
    }
    return out;
}

ContactsCsvFile::ContactsCsvFile(std::string path, const Backend& backend)
    : file_(std::move(path)), backend_(backend) {}

void ContactsCsvFile::begin(const Scene& scene, const RunResult&) {
    scene_ = &scene;
    file_.open();
    std::string head;
    for (const auto& c : contact_columns()) head += (head.empty() ? "" : ",") + c;
    file_.out() << head << '\n';
    file_.check();
}

void ContactsCsvFile::sample(const Sample& s) {
    file_.out() << contact_rows(*scene_, s.t, backend_.contact_points());
    file_.check();
}

void ContactsCsvFile::end(const RunResult&) { file_.close(); }

}  // namespace cairn
