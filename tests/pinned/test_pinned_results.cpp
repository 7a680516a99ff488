// Pinned results: the final state of a few scenes, hashed bit for bit, against the values kept in
// tests/pinned/pinned_results.txt, so that any change of results is seen and must be acknowledged
// by re-pinning (the command is in that file and in docs/development.md). The hash holds for a
// portable build (CAIRN_NATIVE=OFF: x86-64 baseline, no FMA, no AVX kernels); a build with
// -march=native rounds differently, so there the test says so and is skipped (exit 77).
//
//   test_pinned <pin file>           check every pinned run
//   test_pinned <pin file> --repin   run them all again and rewrite the file's values
#include <cinttypes>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "error.hpp"
#include "registry.hpp"
#include "run/runner.hpp"
#include "scene/scene_io.hpp"

using namespace cairn;

namespace {

/// one pinned run: a scene under scenarios/, a backend, its contact mode and the hash
struct Pin {
    std::string scene, backend, mode;
    std::uint64_t hash = 0;
};

/// FNV-1a over the bytes of every double of the final sample (time, every free block's pose and
/// velocities, every probe): equal hashes mean bit-identical states
struct Fnv {
    std::uint64_t h = 1469598103934665603ull;
    void add(double x) {
        unsigned char b[sizeof x];
        std::memcpy(b, &x, sizeof x);
        for (unsigned char c : b) h = (h ^ c) * 1099511628211ull;
    }
    void add(const Vec3& v) { add(v.x()), add(v.y()), add(v.z()); }
};

std::uint64_t final_state_hash(const Pin& p) {
    const Scene scene = load_scene(std::string(CAIRN_SOURCE_DIR) + "/scenarios/" + p.scene);
    auto backend = make_backend(p.backend);
    RunOptions options;
    options.contact_mode = p.mode;
    const RunResult r = run_scene(*backend, scene, options);
    if (r.status != RunStatus::completed) throw Error(p.scene + " on " + p.backend + " did not complete: " + r.message);
    const Sample& s = r.samples.back();
    Fnv f;
    f.add(s.t);
    for (const auto& b : s.blocks) {
        f.add(b.position), f.add(b.velocity), f.add(b.angular_velocity);
        f.add(b.orientation.w()), f.add(b.orientation.x()), f.add(b.orientation.y()), f.add(b.orientation.z());
    }
    for (const auto& q : s.probes) f.add(q);
    return f.h;
}

/// the pin file: comment lines (#) kept as they are, then `scene backend mode hash` per line
std::vector<Pin> read_pins(const std::string& path, std::vector<std::string>& comments) {
    std::ifstream in(path);
    if (!in) throw Error(path + ": cannot read the pinned results");
    std::vector<Pin> pins;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') { comments.push_back(line); continue; }
        std::istringstream ss(line);
        Pin p;
        std::string hex;
        if (!(ss >> p.scene >> p.backend >> p.mode >> hex))
            throw Error(path + ": line '" + line + "' is not `scene backend mode hash`");
        p.hash = std::stoull(hex, nullptr, 16);
        pins.push_back(p);
    }
    return pins;
}

std::string hex(std::uint64_t h) {
    char b[32];
    std::snprintf(b, sizeof b, "%016" PRIx64, h);
    return b;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::cerr << "usage: test_pinned <pin file> [--repin]\n";
        return 2;
    }
    const std::string path = argv[1];
    const bool repin = argc > 2 && std::string(argv[2]) == "--repin";
#ifdef CAIRN_NATIVE_BUILD
    std::cout << (repin ? "cannot re-pin here" : "skipped") << ": the pinned results hold for a portable build (cmake "
                 "-DCAIRN_NATIVE=OFF); this build uses -march=native, whose vector kernels and fused multiply-adds "
                 "round differently\n";
    return repin ? 2 : 77;
#endif
    try {
        std::vector<std::string> comments;
        std::vector<Pin> pins = read_pins(path, comments);
        const auto built = available_backends();
        int changed = 0;
        for (auto& p : pins) {
            bool have = false;
            for (const auto& b : built) have = have || b.name == p.backend;
            if (!have) {
                std::cout << "not built here: " << p.backend << " (" << p.scene << ")\n";
                if (!repin) ++changed;
                continue;
            }
            const std::uint64_t h = final_state_hash(p);
            const bool same = h == p.hash;
            std::cout << (same ? "same     " : "CHANGED  ") << p.scene << " " << p.backend << " " << p.mode << " "
                      << hex(h) << (same ? "" : " (pinned " + hex(p.hash) + ")") << "\n";
            if (!same) ++changed;
            p.hash = h;
        }
        if (repin) {
            std::ostringstream out;
            for (const auto& c : comments) out << c << "\n";
            for (const auto& p : pins) out << p.scene << " " << p.backend << " " << p.mode << " " << hex(p.hash) << "\n";
            std::ofstream(path) << out.str();
            std::cout << "re-pinned " << pins.size() << " runs in " << path << "\n";
            return 0;
        }
        if (changed) {
            std::cout << changed << " pinned result(s) changed or could not be checked. If the change is meant, "
                         "re-pin (see the head of " << path << ") and say why in the commit.\n";
            return 1;
        }
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 2;
    }
}
