#include "output/atomic_write.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "error.hpp"
#include "output/durable.hpp"

namespace cairn {

void write_file_atomic(const std::string& path, const std::function<void(std::ostream&)>& writer) {
    const std::string tmp = path + ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) throw Error("cannot write " + tmp);
        try {
            writer(out);
            out.flush();
        } catch (...) {
            out.close();
            std::remove(tmp.c_str());
            throw;
        }
        if (!out) {
            out.close();
            std::remove(tmp.c_str());
            throw Error("error while writing " + tmp + " (disk full?)");
        }
    }
    std::error_code ec;
    try {
        sync_file(tmp);   // the content is on disk before the name points at it
    } catch (...) {
        std::remove(tmp.c_str());
        throw;
    }
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
        std::remove(tmp.c_str());
        throw Error("cannot rename " + tmp + " to " + path + ": " + ec.message());
    }
    const auto parent = std::filesystem::path(path).parent_path();
    sync_dir(parent.empty() ? std::string(".") : parent.string());
}

void write_text_atomic(const std::string& path, const std::string& text) {
    write_file_atomic(path, [&](std::ostream& out) { out << text; });
}

}  // namespace cairn
