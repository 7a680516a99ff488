#include "output/contacts_csv.hpp"

#include <cstdio>
#include <stdexcept>

#include "output/durable.hpp"

namespace cairn {

std::vector<std::string> contact_columns() {
    return {"t [s]",  "block_a", "block_b",          "x [m]",       "y [m]",       "z [m]",      "nx [-]",
            "ny [-]", "nz [-]",  "normal_force [N]", "shear_x [N]", "shear_y [N]", "shear_z [N]"};
}

std::string contact_rows(const Scene& scene, double t, const std::vector<ContactPoint>& points) {
    auto name = [&](int b) { return b >= 0 && size_t(b) < scene.blocks.size() ? scene.blocks[size_t(b)].name : "?"; };
    std::string out;
    char buf[64];
    auto put = [&](double x) {
        std::snprintf(buf, sizeof buf, ",%.17g", x);
        out += buf;
    };
    for (const ContactPoint& p : points) {
        std::snprintf(buf, sizeof buf, "%.17g", t);
        out += buf;
        out += "," + name(p.block_a) + "," + name(p.block_b);
        for (const Vec3* v : {&p.position, &p.normal}) put(v->x()), put(v->y()), put(v->z());
        put(p.normal_force.dot(p.normal));
        put(p.shear_force.x()), put(p.shear_force.y()), put(p.shear_force.z());
        out += '\n';
    }
    return out;
}

namespace {
/// bytes buffered between writes to the file
constexpr size_t kBufferBytes = size_t(1) << 20;
}  // namespace

ContactsCsvFile::ContactsCsvFile(std::string path, const Backend& backend)
    : path_(std::move(path)), backend_(backend) {}

void ContactsCsvFile::check() const {
    if (!out_) throw std::runtime_error("error while writing " + path_ + " (disk full?)");
}

void ContactsCsvFile::begin(const Scene& scene, const RunResult&) {
    scene_ = &scene;
    buffer_.resize(kBufferBytes);
    out_.rdbuf()->pubsetbuf(buffer_.data(), std::streamsize(buffer_.size()));
    out_.open(path_, std::ios::binary | std::ios::trunc);
    if (!out_) throw std::runtime_error("cannot write " + path_);
    std::string head;
    for (const auto& c : contact_columns()) head += (head.empty() ? "" : ",") + c;
    out_ << head << '\n';
    check();
}

void ContactsCsvFile::sample(const Sample& s) {
    out_ << contact_rows(*scene_, s.t, backend_.contact_points());
    check();
}

void ContactsCsvFile::end(const RunResult&) {
    out_.flush();
    check();
    out_.close();
    if (!out_) throw std::runtime_error("error while closing " + path_ + " (disk full?)");
    sync_file(path_);
}

}  // namespace cairn
