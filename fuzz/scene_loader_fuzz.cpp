// libFuzzer target for the scene loader. One input is up to three parts split by a line "%%":
//   1. a scene (TOML), read as if it were the file <tmp>/scene.toml;
//   2. `--set` overrides, one "key=value" per line;
//   3. the ground-motion CSV, written to <tmp>/g.csv (a scene reaches it with file = "g.csv").
// A cairn::Error is the loader refusing the input, as it should; anything else escaping (another
// exception, a crash, a sanitizer report) is a finding.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "error.hpp"
#include "scene/scene_io.hpp"

namespace fs = std::filesystem;

namespace {

fs::path g_dir;   // this process's scratch directory

/// `text` cut at each line that is exactly "%%"
std::vector<std::string> split_parts(const std::string& text) {
    std::vector<std::string> parts(1);
    size_t from = 0;
    while (from <= text.size()) {
        size_t end = text.find('\n', from);
        if (end == std::string::npos) end = text.size();
        const std::string line = text.substr(from, end - from);
        if (line == "%%" && parts.size() < 3) parts.emplace_back();
        else parts.back() += line + (end < text.size() ? "\n" : "");
        from = end + 1;
    }
    return parts;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    std::string tmpl = (fs::temp_directory_path() / "cairn-fuzz-XXXXXX").string();
    if (!mkdtemp(tmpl.data())) std::abort();
    g_dir = tmpl;
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const auto parts = split_parts(std::string(reinterpret_cast<const char*>(data), size));
    const fs::path csv = g_dir / "g.csv";
    if (parts.size() > 2) std::ofstream(csv, std::ios::binary | std::ios::trunc) << parts[2];
    else fs::remove(csv);
    try {
        std::vector<cairn::Override> overrides;
        if (parts.size() > 1) {
            size_t from = 0;
            const std::string& o = parts[1];
            while (from < o.size()) {
                size_t end = o.find('\n', from);
                if (end == std::string::npos) end = o.size();
                if (end > from) overrides.push_back(cairn::parse_override(o.substr(from, end - from)));
                from = end + 1;
            }
        }
        cairn::Scene scene = cairn::parse_scene(parts[0], (g_dir / "scene.toml").string(), overrides);
        (void)cairn::scene_to_json(scene).dump();   // the run record's view of the scene too
    } catch (const cairn::Error&) {
        // a refused input: the expected outcome for most inputs
    }
    return 0;
}
