#include "run/resume_log.hpp"

#include <cinttypes>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "error.hpp"

namespace cairn {

std::string text_hash(const std::string& text) {
    std::uint64_t h = 14695981039346656037ull;   // the FNV offset basis
    for (unsigned char c : text) h = (h ^ c) * 1099511628211ull;
    char buf[20];
    std::snprintf(buf, sizeof buf, "%016" PRIx64, h);
    return buf;
}

namespace {

/// a record on one line: newlines and tabs become spaces
std::string one_line(std::string s) {
    for (char& c : s)
        if (c == '\n' || c == '\r' || c == '\t') c = ' ';
    return s;
}

}  // namespace

ResumeLog::ResumeLog(std::string path) : path_(std::move(path)) {
    std::ifstream in(path_, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw Error(path_ + ": cannot read the resume log");
    // whole lines only: "key \t outcome \t record \n"
    size_t at = 0;
    for (size_t end; (end = text.find('\n', at)) != std::string::npos; at = end + 1) {
        const std::string line = text.substr(at, end - at);
        const size_t a = line.find('\t'), b = a == std::string::npos ? a : line.find('\t', a + 1);
        if (b == std::string::npos) continue;   // not a line of this log
        entries_[line.substr(0, a)] = Entry{line.substr(a + 1, b - a - 1), line.substr(b + 1)};
    }
    // drop a line cut by an interruption so that the next one starts clean
    std::error_code ec;
    if (at < text.size()) std::filesystem::resize_file(path_, at, ec);
    std::ofstream out(path_, std::ios::app | std::ios::binary);
    if (ec || !out) throw Error(path_ + ": cannot write the resume log");
}

const ResumeLog::Entry* ResumeLog::find(const std::string& key) const {
    const auto it = entries_.find(key);
    return it == entries_.end() ? nullptr : &it->second;
}

void ResumeLog::keep(const std::string& key, const Entry& entry) {
    std::lock_guard<std::mutex> guard(lock_);
    Entry e{one_line(entry.outcome), one_line(entry.record)};
    std::ofstream out(path_, std::ios::app | std::ios::binary);
    out << key << '\t' << e.outcome << '\t' << e.record << '\n';
    out.flush();
    if (!out) throw Error(path_ + ": cannot write the resume log");
    entries_[key] = std::move(e);
}

}  // namespace cairn
