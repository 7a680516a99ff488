#include "study/contact_study.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>

#include "analytic/oracles.hpp"
#include "analytic/winkler_rocking.hpp"
#include "cases/case_util.hpp"
#include "error.hpp"
#include "output/atomic_write.hpp"
#include "report/text.hpp"
#include "run/run_jobs.hpp"
#include "scene/scene_io.hpp"
#include "study/impact_measure.hpp"

namespace cairn::study {

namespace {

constexpr double kRepeatBelow = 2.0;   ///< s: runs at least this long are timed once
constexpr int kDefaultSubdivision = 4;  ///< the overlap scheme's default (docs/dem.md)
constexpr double kPaperSpacing = 0.1;   ///< the paper's grid, m

std::string num(double v) {
    char b[40];
    std::snprintf(b, sizeof b, "%.10g", v);
    return b;
}

/// the scene of a point: kn = ks, the scheme with its grid or sub-division, the model, sampled
/// every millisecond until past the later of the two references
Scene point_scene(const std::string& path, const ContactStudyPoint& p, double duration) {
    std::vector<Override> o{parse_override("contact.kn=" + num(p.kn)), parse_override("contact.ks=" + num(p.kn)),
                            parse_override("contact.scheme=\"" + p.scheme + "\""),
                            parse_override("run.duration=" + num(duration)), parse_override("run.output_interval=0.001")};
    if (p.scheme == "paper") o.push_back(parse_override("contact.grid_spacing=" + num(p.grid_spacing)));
    else o.push_back(parse_override("contact.subdivision=" + std::to_string(p.subdivision)));
    Scene s = load_scene(path, o);
    apply_model(s, p.model);
    return s;
}

/// the rigid block on a Winkler base of the scene's kn, its faces cut as the overlap's default
oracle::WinklerRocking winkler_of(const Scene& s) {
    const int a = s.reference->block;
    const auto hb = cases::housner_block(s);
    const Vec3 axis = cases::rocking_axis(s);
    double lo = 1e300, hi = -1e300;
    for (const auto& c : s.blocks.at(size_t(a)).corners) lo = std::min(lo, c.dot(axis)), hi = std::max(hi, c.dot(axis));
    oracle::WinklerRocking w{2.0 * hb.b, 2.0 * hb.h, hi - lo, cases::block_mass(s, a), cases::gravity(s),
                             s.contact.kn, s.contact.ks, s.contact.friction};
    w.cells_across = kDefaultSubdivision;
    w.cells_up = kDefaultSubdivision;
    return w;
}

/// contact points of the block standing upright on its base, after two steps
int standing_points(const Scene& scene, const BackendInfo& dem) {
    Scene s = scene;
    // the top of the fixed blocks, where the block stands (m)
    double top = -1e300;
    for (const auto& f : s.blocks)
        if (f.fixed)
            for (const auto& c : f.corners) top = std::max(top, (f.position + f.orientation * c).z());
    BlockDef& b = s.blocks.at(size_t(s.reference->block));
    double low = 1e300;   // the block frame's lowest corner
    for (const auto& c : b.corners) low = std::min(low, c.z());
    b.orientation = Quat::Identity();
    b.position.z() = top - low;
    auto backend = dem.make();
    backend->build(s, RunOptions{});
    for (int i = 0; i < 2; ++i)
        if (backend->step() != StepStatus::ok) return 0;
    return backend->sample().contacts;
}

}  // namespace

std::string ContactStudyPoint::label() const {
    char b[64];
    if (scheme == "paper") std::snprintf(b, sizeof b, "paper %g m", grid_spacing);
    else std::snprintf(b, sizeof b, "overlap n = %d", subdivision);
    return std::string(b) + (model == "rigid" ? "" : " (" + model + ")");
}

std::vector<ContactStudyPoint> run_contact_study(const std::string& path, const ContactStudyOptions& options,
                                            const std::vector<BackendInfo>& backends) {
    const auto dem = std::find_if(backends.begin(), backends.end(), [](const BackendInfo& b) { return b.name == "dem"; });
    if (dem == backends.end()) throw Error("study contact: the dem backend is not built");
    std::vector<ContactStudyPoint> points;
    for (double kn : options.kns) {
        ContactStudyPoint p;
        p.kn = kn;
        p.model = "rigid";
        p.scheme = "paper";
        for (double s : options.spacings) p.grid_spacing = s, points.push_back(p);
        p.grid_spacing = 0.0;
        p.scheme = "overlap";
        for (int n : options.subdivisions) p.subdivision = n, points.push_back(p);
        p.model = "deformable";
        p.subdivision = kDefaultSubdivision;
        points.push_back(p);
        p.scheme = "paper";
        p.subdivision = 0;
        p.grid_spacing = kPaperSpacing;
        points.push_back(p);
    }
    std::vector<Scene> scenes;
    for (auto& p : points) {
        // the references first: the run goes 20 % past the later one
        const Scene probe = point_scene(path, p, 1.0);
        if (!probe.reference || probe.reference->values.count("theta0") == 0)
            throw Error(path + ": [reference]: the contact study needs a rocking reference with theta0");
        const double th0 = probe.reference->values.at("theta0");
        p.t_housner = cases::housner_block(probe).first_impact(th0);
        const auto tr = winkler_of(probe).rock(th0, 3.0 * p.t_housner, 1e-3);
        p.t_winkler = tr.crossings.empty() ? NAN : tr.crossings.front();
        const double later = std::isfinite(p.t_winkler) ? std::max(p.t_winkler, p.t_housner) : 2.0 * p.t_housner;
        scenes.push_back(point_scene(path, p, 1.2 * later));
        p.points = standing_points(scenes.back(), *dem);
    }
    std::vector<RunSpec> jobs;
    for (size_t i = 0; i < points.size(); ++i) {
        RunSpec s;
        s.scene = &scenes[i];
        s.backend = "dem";
        s.repeats = std::max(1, options.repeats);
        s.label = "kn " + num(points[i].kn) + " " + points[i].label();
        jobs.push_back(std::move(s));
    }
    JobsOptions jo;
    jo.jobs = options.jobs;
    jo.quiet = options.quiet;
    jo.tag = "study contact";
    jo.repeat_below = kRepeatBelow;
    run_jobs(jobs, backends, jo, [&](size_t i, JobResult& r) {
        ContactStudyPoint& p = points[i];   // each job writes its own point
        p.wall_seconds = r.median_wall;
        p.dt = r.result.dt;
        p.steps = r.result.steps;
        if (r.outcome != Outcome::completed) {
            p.status = r.message.empty() ? "did not complete" : r.message;
            return;
        }
        const Scene& s = scenes[i];
        const auto imp = first_rocking_impact(r.result.samples, cases::free_index(s, s.reference->block),
                                              cases::rocking_axis(s), 0.005, 0.03);
        p.status = imp.found ? "completed" : "completed: no impact within the run (overturned?)";
        if (imp.found) p.t_impact = imp.time;
    });
    return points;
}

namespace {

const char* kHeader = "kn,scheme,grid_spacing,subdivision,model,points,t_impact,t_housner,t_winkler,housner_error,"
                      "winkler_error,dt,steps,wall_seconds,status";

double to_num(const std::string& s) { return s.empty() ? NAN : std::stod(s); }

}  // namespace

void write_contact_csv(const std::string& path, const std::vector<ContactStudyPoint>& points) {
    write_file_atomic(path, [&](std::ostream& o) {
        o << kHeader << "\n";
        for (const auto& p : points) {
            std::string status;
            for (char c : p.status) status += c == '"' ? std::string("\"\"") : std::string(1, c);
            auto n = [](double v) { return report::number_text(v, 10); };
            o << n(p.kn) << "," << p.scheme << "," << n(p.grid_spacing) << "," << p.subdivision << "," << p.model << ","
              << p.points << "," << n(p.t_impact) << "," << n(p.t_housner) << "," << n(p.t_winkler) << ","
              << n(p.housner_error()) << "," << n(p.winkler_error()) << "," << n(p.dt) << "," << p.steps << ","
              << n(p.wall_seconds) << ",\"" << status << "\"\n";
        }
    });
}

std::vector<ContactStudyPoint> read_contact_csv(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw Error(path + ": cannot open the contact study's CSV (run `cairn study contact` first)");
    std::string line;
    std::getline(in, line);
    if (line != kHeader) throw Error(path + ":1: not a contact study CSV (unexpected header)");
    std::vector<ContactStudyPoint> out;
    for (int ln = 2; std::getline(in, line); ++ln) {
        if (line.empty()) continue;
        const auto f = report::split_csv_line(line);
        const std::string where = path + ":" + std::to_string(ln);
        if (f.size() != 15) throw Error(where + ": expected 15 fields, found " + std::to_string(f.size()));
        try {
            ContactStudyPoint p;
            p.kn = to_num(f[0]);
            p.scheme = f[1];
            p.grid_spacing = to_num(f[2]);
            p.subdivision = std::stoi(f[3]);
            p.model = f[4];
            p.points = std::stoi(f[5]);
            p.t_impact = to_num(f[6]);
            p.t_housner = to_num(f[7]);
            p.t_winkler = to_num(f[8]);
            p.dt = to_num(f[11]);
            p.steps = std::stoll(f[12]);
            p.wall_seconds = to_num(f[13]);
            p.status = f[14];
            if (p.scheme != "paper" && p.scheme != "overlap") throw Error("scheme " + p.scheme);
            out.push_back(std::move(p));
        } catch (const std::exception& e) {
            throw Error(where + ": not a number where one was expected (" + e.what() + ")");
        }
    }
    return out;
}

}  // namespace cairn::study
