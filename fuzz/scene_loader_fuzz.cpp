// libFuzzer target for the scene loader: the input format is in scene_input.hpp. A cairn::Error is
// the loader refusing the input, as it should; anything else escaping (another exception, a crash,
// a sanitizer report) is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <stdlib.h>   // mkdtemp

#include "error.hpp"
#include "scene_input.hpp"

namespace {
std::filesystem::path g_dir;   // this process's scratch directory
}

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    std::string tmpl = (std::filesystem::temp_directory_path() / "cairn-fuzz-XXXXXX").string();
    if (!mkdtemp(tmpl.data())) std::abort();
    g_dir = tmpl;
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        cairn::fuzz::load_input(std::string(reinterpret_cast<const char*>(data), size), g_dir);
    } catch (const cairn::Error&) {
        // a refused input: the expected outcome for most inputs
    }
    return 0;
}
