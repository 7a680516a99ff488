// reading a sweep plan: every key checked, every error naming the file, line, key and value
#include "sweep/sweep_plan.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <toml++/toml.h>

#include "error.hpp"
#include "scene/scene_limits.hpp"
#include "scene/toml_reader.hpp"

namespace fs = std::filesystem;

namespace cairn::sweep {

namespace {

using scene_detail::Item;
using scene_detail::Sources;
using scene_detail::TableReader;

constexpr std::size_t kMaxList = 1000;   // most scenes, backends, records, intensities, axis values
constexpr int kMaxAxes = 8;

/// a name that can become part of a file name and a CSV cell
void check_name(const Item& at, const std::string& name) {
    bool ok = !name.empty() && name.size() <= 64;
    for (char c : name)
        ok = ok && ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-');
    at.check(ok, "a name of 1 to 64 letters, digits, '_' or '-' is expected");
}

/// a node's value as TOML text (for an override), the TOML way
std::string toml_text(const toml::node& node) {
    std::ostringstream out;
    node.visit([&](auto&& v) { out << toml::toml_formatter{v}; });
    return out.str();
}

/// an array item with at most kMaxList elements
const toml::array& bounded_array(const Item& it) {
    const toml::array& a = it.array();
    it.check(!a.empty(), "an array of at least one value is expected");
    it.check(a.size() <= kMaxList, "at most " + std::to_string(kMaxList) + " values are allowed");
    return a;
}

/// the strings of `it`: a string or an array of strings
std::vector<std::string> strings(const Item& it) {
    if (!it.node().is_array()) return {it.string()};
    std::vector<std::string> out;
    const auto& a = bounded_array(it);
    for (std::size_t i = 0; i < a.size(); ++i) out.push_back(it.element(i).string());
    return out;
}

/// the leaves of a table of overrides as dotted keys (nested non-inline tables are walked)
void flatten(const Sources& src, const toml::table& t, const std::string& prefix,
             const std::function<void(const std::string&, const Item&)>& leaf) {
    for (const auto& [k, v] : t) {
        const std::string key = prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
        if (auto sub = v.as_table(); sub && !sub->is_inline()) flatten(src, *sub, key, leaf);
        else leaf(key, Item(src, &v, key));
    }
}

RecordSpec read_record(const TableReader& records, const std::string& name, const fs::path& plan_dir) {
    const Item self = records.get(name);
    check_name(self, name);
    const TableReader r = self.reader({"file", "units", "time_column", "acceleration_column", "pulse",
                                       "frequency", "cycles", "source"});
    RecordSpec rec;
    rec.name = name;
    const Item file = r.get("file"), pulse = r.get("pulse");
    if (file.operator bool() == pulse.operator bool())
        self.fail("give either file (a recorded ground motion) or pulse (a synthetic one)");
    if (Item s = r.get("source")) rec.source = s.string();
    if (file) {
        fs::path p(file.string());
        if (p.is_relative()) p = plan_dir / p;
        std::error_code ec;
        file.check(fs::is_regular_file(p, ec), "no such file (" + p.lexically_normal().string() + ")");
        rec.file = fs::absolute(p).lexically_normal().string();
        if (Item u = r.get("units")) {
            rec.units = u.string();
            u.check(rec.units == "g" || rec.units == "m/s2", "expected \"g\" or \"m/s2\"");
        }
        if (Item c = r.get("time_column")) rec.time_column = c.string();
        if (Item c = r.get("acceleration_column")) rec.acceleration_column = c.string();
        for (const auto* k : {"frequency", "cycles"})
            if (Item it = r.get(k)) it.fail("only for a synthetic pulse");
        return rec;
    }
    rec.pulse = pulse.string();
    pulse.check(rec.pulse == "sine" || rec.pulse == "cosine" || rec.pulse == "ricker",
                "expected \"sine\", \"cosine\" or \"ricker\"");
    const Item f = r.require("frequency");
    rec.frequency = f.number();
    f.check(rec.frequency >= 0.05 && rec.frequency <= 100.0, "a frequency from 0.05 to 100 Hz is expected");
    if (Item c = r.get("cycles")) {
        c.check(rec.pulse != "ricker", "a Ricker wavelet has no cycle count");
        rec.cycles = c.small_integer();
        c.check(rec.cycles >= 1 && rec.cycles <= 20, "from 1 to 20 cycles are expected");
    }
    for (const auto* k : {"units", "time_column", "acceleration_column"})
        if (Item it = r.get(k)) it.fail("only for a record file (a pulse is written in g)");
    if (rec.source.empty()) rec.source = "synthetic " + rec.pulse + " pulse";
    return rec;
}

}  // namespace

BackendVariant backend_variant(const std::string& name) {
    BackendVariant v;
    const auto dash = name.find('-');
    v.backend = name.substr(0, dash);
    if (dash == std::string::npos) return v;
    const std::string suffix = name.substr(dash + 1);
    if (suffix == "matched" && v.backend != "dem") v.contact = "matched";
    else if (suffix == "deformable" && v.backend == "dem") v.model = "deformable";
    else if (suffix == "rigid") v.model = v.backend == "dem" ? "rigid" : "";
    else
        throw Error("expected a backend name or a variant: dem-rigid, dem-deformable, or <engine>-rigid, "
                    "<engine>-matched");
    return v;
}

SweepPlan read_sweep_plan(const std::string& path,
                          const std::function<std::string(const std::string&)>& resolve_scene) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path + ": cannot open the sweep plan");
    std::string text;
    {
        std::ostringstream s;
        // read at most one byte past the limit, so that a huge file is refused without being read
        std::vector<char> buf(kMaxPlanBytes + 1);
        in.read(buf.data(), std::streamsize(buf.size()));
        if (std::size_t(in.gcount()) > kMaxPlanBytes)
            throw Error(path + ": a sweep plan of more than " + std::to_string(kMaxPlanBytes) + " bytes");
        text.assign(buf.data(), std::size_t(in.gcount()));
    }
    check_toml_limits(text, path);
    Sources src;
    src.add(path, text);
    toml::table root;
    try {
        root = toml::parse(text, path);
    } catch (const toml::parse_error& e) {
        const auto& at = e.source().begin;
        throw Error(path + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) +
                    ": TOML syntax error: " + std::string(e.description()));
    }
    const TableReader r(src, root, "",
                        {"kind", "description", "scene", "scenes", "backends", "block", "overturn_angle", "repeats",
                         "intensities", "set", "records", "axes"});
    const fs::path dir = fs::absolute(fs::path(path)).parent_path();
    SweepPlan plan;
    plan.path = path;
    if (Item k = r.get("kind")) {
        plan.kind = k.string();
        k.check(plan.kind == "grid" || plan.kind == "fragility", "expected \"grid\" or \"fragility\"");
    }
    const Item scene = r.get("scene"), scenes = r.get("scenes");
    if (scene && scenes) scenes.fail("give scene or scenes, not both");
    const Item scene_item = scene ? scene : scenes ? scenes : r.require("scenes");
    for (const auto& s : strings(scene_item)) {
        std::error_code ec;
        const fs::path local = dir / s;
        try {
            plan.scenes.push_back(resolve_scene(fs::is_regular_file(local, ec) ? local.string() : s));
        } catch (const Error& e) {
            scene_item.fail(e.what());
        }
        plan.scene_names.push_back(s);
    }
    {
        const Item b = r.require("backends");
        plan.backends = strings(b);
        std::set<std::string> seen;
        for (const auto& n : plan.backends) {
            check_name(b, n);
            b.check(seen.insert(n).second, "backend " + n + " is named twice");
            try {
                backend_variant(n);
            } catch (const Error& e) {
                b.fail(n + ": " + e.what());
            }
        }
    }
    if (Item b = r.get("block")) plan.block = b.string();
    if (Item a = r.get("overturn_angle")) {
        plan.overturn_angle = a.number();
        a.check(plan.overturn_angle > 0.0 && plan.overturn_angle < M_PI / 2, "an angle in (0, π/2) rad is expected");
    }
    if (Item n = r.get("repeats")) {
        plan.repeats = n.small_integer();
        n.check(plan.repeats >= 1 && plan.repeats <= 100, "from 1 to 100 repeats are expected");
    }
    if (Item in = r.get("intensities")) {
        const auto& a = bounded_array(in);
        for (std::size_t i = 0; i < a.size(); ++i) {
            const Item e = in.element(i);
            const double v = e.number();
            e.check(v > 0.0 && v <= 100.0, "a peak ground acceleration in (0, 100] g is expected");
            plan.intensities.push_back(v);
        }
    }
    if (Item s = r.get("set")) {
        flatten(src, s.table(), "", [&](const std::string& key, const Item& v) {
            plan.set.push_back(key + "=" + toml_text(v.node()));
        });
        if (plan.set.size() > kMaxList) s.fail("too many overrides");
    }
    if (Item recs = r.get("records")) {
        const TableReader t(src, recs.table(), "records");
        for (const auto& [k, v] : recs.table()) plan.records.push_back(read_record(t, std::string(k.str()), dir));
        recs.check(plan.records.size() <= kMaxList, "too many records");
    }
    if (Item ax = r.get("axes")) {
        flatten(src, ax.table(), "", [&](const std::string& key, const Item& v) {
            Axis axis{key, {}};
            const auto& a = bounded_array(v);
            for (std::size_t i = 0; i < a.size(); ++i) axis.values.push_back(toml_text(*a.get(i)));
            plan.axes.push_back(std::move(axis));
        });
        ax.check(int(plan.axes.size()) <= kMaxAxes, "at most " + std::to_string(kMaxAxes) + " axes are allowed");
    }
    if (plan.kind == "fragility") {
        const Item at = r.get("kind");
        at.check(plan.intensities.size() >= 2, "a fragility plan needs intensities (at least two)");
    }
    // the size of the sweep, counted without overflow
    double runs = double(plan.scenes.size()) * double(plan.backends.size()) *
                  double(std::max<std::size_t>(1, plan.records.size())) *
                  double(std::max<std::size_t>(1, plan.intensities.size())) * double(plan.repeats);
    for (const auto& a : plan.axes) runs *= double(a.values.size());
    if (runs > double(kMaxPlanRuns))
        throw Error(path + ": the plan expands into " + message_number(runs, 6) + " runs, more than the limit of " +
                    std::to_string(kMaxPlanRuns));
    return plan;
}

}  // namespace cairn::sweep
