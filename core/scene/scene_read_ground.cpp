// [ground_motion]: ground acceleration records, one along a direction or one per world axis, from
// CSV files or inline arrays, turned into one inertial body load −m·a_g(t) per free block and
// component: every backend applies them as loads, with their work in W_external.
#define CSV_IO_NO_THREAD
#include <limits>   // libfccp's csv.h uses std::numeric_limits without including it
#if defined(__GNUC__) && !defined(__clang__)   // a GCC-only warning; clang does not know it
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wstringop-truncation"   // in the library's own error-name copy
#endif
#include <libfccp/csv.h>
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "error.hpp"
#include "geometry/hexahedron.hpp"
#include "scene/scene_read.hpp"

namespace cairn {

double TimeSeries::at(double t) const {
    if (time.empty() || t < time.front() || t > time.back()) return 0.0;
    auto hi = std::upper_bound(time.begin(), time.end(), t);
    if (hi == time.end()) return value.back();
    const size_t j = size_t(hi - time.begin()), i = j - 1;
    const double w = (t - time[i]) / (time[j] - time[i]);
    return (1.0 - w) * value[i] + w * value[j];
}

namespace scene_detail {

namespace {

// two named columns of a CSV file ('#' starts a comment line)
TimeSeries read_csv(const Item& file_item, const std::string& path, const std::string& time_column,
                    const std::string& value_column) {
    TimeSeries s;
    try {
        io::CSVReader<2, io::trim_chars<' ', '\t'>, io::no_quote_escape<','>, io::throw_on_overflow,
                      io::single_line_comment<'#'>>
            in(path);
        in.read_header(io::ignore_extra_column, time_column, value_column);
        double t, v;
        while (in.read_row(t, v)) {
            s.time.push_back(t);
            s.value.push_back(v);
        }
    } catch (const io::error::can_not_open_file&) {
        file_item.fail("cannot open the ground-motion file (" + path + ")");
    } catch (const io::error::base& e) {
        file_item.fail(std::string("cannot read the ground-motion file: ") + e.what());
    }
    return s;
}

// one acceleration record from table `g` (a file or inline arrays, units, scale), in m/s² and
// multiplied by `outer_scale` (the top-level scale when `g` is a component table)
GroundComponent read_record(const TableReader& g, const Scene& scene, double outer_scale, const Item& outer_scale_item) {
    GroundComponent gm;
    Item file = g.get("file"), time = g.get("time"), accel = g.get("acceleration");
    if (file && (time || accel)) file.fail("give a file or inline time and acceleration arrays, not both");
    if (file) {
        std::filesystem::path p(file.string());
        if (p.is_relative()) p = std::filesystem::path(scene.source).parent_path() / p;
        std::string tcol = "t_s", acol = "accel_g";
        if (Item it = g.get("time_column")) tcol = it.string();
        if (Item it = g.get("acceleration_column")) acol = it.string();
        gm.acceleration = read_csv(file, p.lexically_normal().string(), tcol, acol);
        gm.source = p.lexically_normal().string() + " (" + acol + ")";
    } else {
        if (!time) g.require("file");   // reports the missing key
        Item a = g.require("acceleration");
        const auto& ta = time.array();
        gm.acceleration.time = time.numbers(ta.size());
        gm.acceleration.value = a.numbers(ta.size());
        gm.source = "inline";
    }
    const auto& ts = gm.acceleration.time;
    const Item& record = file ? file : time;
    record.check(ts.size() >= 2, "the record needs at least 2 samples");
    for (size_t i = 0; i < ts.size(); ++i)
        if (!std::isfinite(ts[i]) || (i > 0 && !(ts[i] > ts[i - 1])))
            record.fail("times must increase strictly and be finite (sample " + std::to_string(i) +
                        ", t = " + message_number(ts[i], 6) + " s)");
    double unit = 1.0;
    if (Item it = g.get("units")) {
        const std::string u = it.string();
        it.check(u == "g" || u == "m/s2", "expected \"g\" (× 9.81 m/s²) or \"m/s2\"");
        unit = u == "g" ? 9.81 : 1.0;
    } else if (file) {
        unit = 9.81;   // the default column accel_g is in g
    }
    double scale = outer_scale;
    if (Item it = g.get("scale")) scale *= it.number();
    // every sample, the first too, must be finite as the engines will see it
    for (size_t i = 0; i < gm.acceleration.value.size(); ++i) {
        const double raw = gm.acceleration.value[i], v = raw * unit * scale;
        if (std::isfinite(v)) {
            gm.acceleration.value[i] = v;
            continue;
        }
        const Item scale_item = g.get("scale") ? g.get("scale") : outer_scale_item;
        const Item culprit = std::isfinite(raw) && scale_item ? scale_item : (file ? file : accel);
        culprit.fail("sample " + std::to_string(i) + ": acceleration " + message_number(raw, 6) + " × units " +
                     message_number(unit, 6) + " × scale " + message_number(scale, 6) + " is not finite");
    }
    return gm;
}

}  // namespace

void read_ground_motion(const TableReader& root, Scene& scene) {
    Item section = root.get("ground_motion");
    if (!section) return;
    static const std::vector<std::string> record_keys = {"file", "time_column", "acceleration_column", "time",
                                                         "acceleration", "units", "scale"};
    std::vector<std::string> top_keys = record_keys;
    for (const char* k : {"direction", "start", "x", "y", "z"}) top_keys.push_back(k);
    TableReader g = sub_table(root, "ground_motion", top_keys);
    GroundMotion gm;
    const bool per_axis = g.get("x") || g.get("y") || g.get("z");
    if (per_axis) {
        // one record per world axis; the top level holds only start and a common scale
        for (const auto& k : record_keys)
            if (k != "scale" && g.get(k)) g.get(k).fail("give one record, or records per axis (x, y, z), not both");
        if (Item d = g.get("direction")) d.fail("the per-axis records (x, y, z) have their own directions");
        const Item outer = g.get("scale");
        const double outer_scale = outer ? outer.number() : 1.0;
        const char* axes[3] = {"x", "y", "z"};
        for (int a = 0; a < 3; ++a) {
            if (!g.get(axes[a])) continue;
            GroundComponent c = read_record(sub_table(g, axes[a], record_keys), scene, outer_scale, outer);
            c.direction = Vec3::Unit(a);
            gm.components.push_back(std::move(c));
        }
    } else {
        GroundComponent c = read_record(g, scene, 1.0, Item(root.sources(), nullptr, ""));
        if (Item it = g.get("direction")) {
            c.direction = it.vec3();
            it.check(c.direction.norm() > 0.0, "the direction must not be zero");
            c.direction.normalize();
        }
        gm.components.push_back(std::move(c));
    }
    if (Item it = g.get("start")) {
        gm.start = it.number();
        it.check(gm.start >= 0.0, "must be >= 0");
    }
    scene.ground_motion = gm;
    add_ground_motion_loads(scene);
}

void add_ground_motion_loads(Scene& scene) {
    if (!scene.ground_motion) return;
    // the inertial force on each free block: −m·a_g(t) per component, spread like its mass; a
    // vertical component adds to gravity (a_z > 0, the ground accelerating up, presses harder)
    for (const GroundComponent& c : scene.ground_motion->components) {
        auto history = std::make_shared<const TimeSeries>(c.acceleration);
        for (size_t b = 0; b < scene.blocks.size(); ++b) {
            const BlockDef& def = scene.blocks[b];
            if (def.fixed) continue;
            MassProperties mp = mass_properties(def.corners, scene.materials[size_t(def.material)].density);
            LoadDef l;
            l.block = int(b);
            l.force = -mp.mass * c.direction;
            l.point = mp.centre;
            l.start = scene.ground_motion->start;
            l.history = history;
            l.body = true;
            scene.loads.push_back(l);
        }
    }
}

}  // namespace scene_detail
}  // namespace cairn
