#include "output/buffered_file.hpp"

#include <stdexcept>

#include "output/durable.hpp"

namespace cairn {

namespace {
/// bytes buffered between writes to the file
constexpr size_t kBufferBytes = size_t(1) << 20;
}  // namespace

void BufferedFile::open() {
    buffer_.resize(kBufferBytes);
    out_.rdbuf()->pubsetbuf(buffer_.data(), std::streamsize(buffer_.size()));
    out_.open(path_, std::ios::binary | std::ios::trunc);
    if (!out_) throw std::runtime_error("cannot write " + path_);
}

void BufferedFile::check() const {
    if (!out_) throw std::runtime_error("error while writing " + path_ + " (disk full?)");
}

void BufferedFile::close() {
    out_.flush();
    check();
    out_.close();
    if (!out_) throw std::runtime_error("error while closing " + path_ + " (disk full?)");
    sync_file(path_);
}

}  // namespace cairn
