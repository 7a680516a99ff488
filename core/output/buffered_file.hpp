#pragma once
/// An output file streamed through a large buffer, for the sinks that write as a run goes.

#include <fstream>
#include <string>
#include <vector>

namespace cairn {

/// A file written through a 1 MiB buffer. Every failure throws std::runtime_error naming the file.
class BufferedFile {
public:
    explicit BufferedFile(std::string path) : path_(std::move(path)) {}
    /// create (or truncate) the file; throws "cannot write PATH"
    void open();
    /// the stream to write to (after open())
    std::ostream& out() { return out_; }
    /// throws "error while writing PATH (disk full?)" once a write failed
    void check() const;
    /// flush, close and fsync; throws if any of it fails
    void close();
    const std::string& path() const { return path_; }

private:
    std::string path_;
    std::vector<char> buffer_;
    std::ofstream out_;
};

}  // namespace cairn
