#pragma once
/// Resuming a job list: the jobs that ended are kept in a file, one line each, and a job whose key
/// is there is not run again (run/run_jobs.hpp). A line holds the job's key (text_hash of its scene,
/// backend and options), its outcome and the caller's record of its result.

#include <cstdint>
#include <map>
#include <mutex>
#include <string>

namespace cairn {

/// FNV-1a of `text`, 64 bits, as 16 hex digits (the same text gives the same id on every machine)
std::string text_hash(const std::string& text);

/// The finished jobs of earlier invocations of one job list, and the ones this one adds.
class ResumeLog {
public:
    /// One kept job.
    struct Entry {
        std::string outcome;   ///< to_string(Outcome) of the job
        std::string record;    ///< the caller's text of its result (one line)
    };
    /// reads `path` when it exists (a last line cut by an interruption is left out) and appends
    /// to it; throws cairn::Error naming the path when it cannot be read or written
    explicit ResumeLog(std::string path);
    /// the entry kept for `key`, or nullptr
    const Entry* find(const std::string& key) const;
    /// keeps a job (one whole line, flushed before returning); thread-safe
    void keep(const std::string& key, const Entry& entry);
    /// the file's path
    const std::string& path() const { return path_; }

private:
    std::string path_;
    std::map<std::string, Entry> entries_;
    std::mutex lock_;
};

}  // namespace cairn
