#pragma once
/// Writing a result file so that a crash or an error never leaves a half-written file over an old
/// one: the content goes to "<path>.tmp", which is fsynced and renamed over <path> only once
/// complete, and the directory is fsynced after the rename.

#include <functional>
#include <ostream>
#include <string>

namespace cairn {

/// write `path` through "<path>.tmp" + rename; if `writer` throws, <path> is untouched, the temporary
/// file is removed and the exception propagates; throws cairn::Error when the file cannot be written
void write_file_atomic(const std::string& path, const std::function<void(std::ostream&)>& writer);

/// the same for a whole text
void write_text_atomic(const std::string& path, const std::string& text);

}  // namespace cairn
