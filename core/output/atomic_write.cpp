#include "output/atomic_write.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "error.hpp"

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
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
        std::remove(tmp.c_str());
        throw Error("cannot rename " + tmp + " to " + path + ": " + ec.message());
    }
}

void write_text_atomic(const std::string& path, const std::string& text) {
    write_file_atomic(path, [&](std::ostream& out) { out << text; });
}

}  // namespace cairn
