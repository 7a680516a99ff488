#include "report/replay.hpp"

#include <algorithm>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "error.hpp"
#include "geometry/hexahedron.hpp"
#include "report/text.hpp"

namespace cairn {

// the bundled script (replay_bundle.cpp, generated at build time from report/web/)
extern const bool kReplayAvailable;
extern const char* const kReplayBundleJs;

namespace {

/// a number short enough for a page, close enough for a picture (6 significant digits)
double short_number(double x) { return std::strtod(message_number(x, 6).c_str(), nullptr); }

nlohmann::json run_json(const ReplayRun& r) {
    nlohmann::json blocks = nlohmann::json::array();
    for (const auto& b : r.blocks) {
        nlohmann::json corners = nlohmann::json::array();
        for (const auto& c : b.corners) corners.push_back({short_number(c.x()), short_number(c.y()), short_number(c.z())});
        blocks.push_back({{"name", b.name}, {"fixed", b.fixed}, {"corners", corners}});
    }
    nlohmann::json poses = nlohmann::json::array();
    for (const auto& p : r.poses) {
        nlohmann::json row = nlohmann::json::array();
        for (double x : p) row.push_back(short_number(x));
        poses.push_back(row);
    }
    nlohmann::json t = nlohmann::json::array();
    for (double x : r.t) t.push_back(short_number(x));
    const nlohmann::json up = {short_number(r.up.x()), short_number(r.up.y()), short_number(r.up.z())};
    return {{"label", r.label}, {"up", up}, {"blocks", blocks}, {"t", t}, {"poses", poses}};
}

}  // namespace

ReplayRun replay_run(const std::string& label, const Scene& scene) {
    ReplayRun r;
    r.label = label;
    if (scene.gravity.norm() > 0.0) r.up = (-scene.gravity.normalized()).array() + 0.0;   // + 0: no −0 on the page
    for (const auto& def : scene.blocks) {
        ReplayBlock b;
        b.name = def.name;
        b.fixed = def.fixed;
        const Vec3 com = mass_properties(def.corners, 1.0).centre;
        for (int k = 0; k < 8; ++k)
            b.corners[k] = def.fixed ? Vec3(def.position + def.orientation * def.corners[k]) : Vec3(def.corners[k] - com);
        r.blocks.push_back(b);
    }
    return r;
}

size_t replay_frame_limit(size_t free_blocks) {
    const size_t by_size = kMaxReplayNumbers / (7 * std::max<size_t>(1, free_blocks));
    return std::max(kMinReplayFrames, std::min(kMaxReplayFrames, by_size));
}

void add_frame(ReplayRun& r, const Sample& s) {
    if (r.seen++ % r.stride != 0) return;
    std::vector<double> p;
    p.reserve(7 * s.blocks.size());
    for (const auto& b : s.blocks) {
        const Quat& q = b.orientation;
        p.insert(p.end(), {b.position.x(), b.position.y(), b.position.z(), q.w(), q.x(), q.y(), q.z()});
    }
    r.t.push_back(s.t);
    r.poses.push_back(std::move(p));
    if (r.t.size() < replay_frame_limit(s.blocks.size())) return;
    // too many frames: keep every other one (frame k then holds sample k·stride)
    size_t k = 0;
    for (size_t i = 0; i < r.t.size(); i += 2, ++k) {
        r.t[k] = r.t[i];
        r.poses[k] = std::move(r.poses[i]);
    }
    r.t.resize(k);
    r.poses.resize(k);
    r.stride *= 2;
}

bool replay_available() { return kReplayAvailable; }

std::string replay_html(const std::string& title, const std::vector<ReplayRun>& runs) {
    if (!kReplayAvailable)
        throw Error("this cairn was built without the 3-D replay: node and npm were not found when it was "
                    "built (scripts/setup.sh installs them; then rebuild)");
    nlohmann::json data = {{"title", title}, {"runs", nlohmann::json::array()}};
    for (const auto& r : runs) data["runs"].push_back(run_json(r));
    // '<' only occurs inside JSON strings, where \u003c means the same: no "</script>" can close
    // the script early, whatever the scene's names hold
    std::string json;
    for (char c : data.dump()) json += c == '<' ? std::string("\\u003c") : std::string(1, c);
    std::string page;
    page += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + report::html_text(title) +
            "</title>\n<style>\n"
            "body { margin: 0; font-family: sans-serif; background: #fff; color: #222; }\n"
            "#bar { display: flex; gap: 0.8em; align-items: center; padding: 6px 10px; }\n"
            "#bar h1 { font-size: 1em; margin: 0 1em 0 0; }\n"
            "#time { flex: 1; }\n"
            "#readout { font-variant-numeric: tabular-nums; min-width: 14em; }\n"
            "#views { display: flex; flex-wrap: wrap; gap: 6px; padding: 0 6px 6px; }\n"
            ".view { flex: 1 1 320px; min-width: 260px; }\n"
            ".view canvas { width: 100%; height: 360px; display: block; border: 1px solid #ccc; }\n"
            ".label { font-size: 0.9em; padding: 2px 0; }\n"
            "</style>\n</head>\n<body>\n"
            "<div id=\"bar\"><h1 id=\"title\"></h1><button id=\"play\">play</button>"
            "<input id=\"time\" type=\"range\" min=\"0\" max=\"1\" step=\"0.001\" value=\"0\" aria-label=\"time (s)\">"
            "<span id=\"readout\"></span></div>\n<div id=\"views\"></div>\n"
            "<script>window.CAIRN_REPLAY = " + json + ";</script>\n<script>\n";
    page += kReplayBundleJs;
    page += "\n</script>\n</body>\n</html>\n";
    return page;
}

}  // namespace cairn
