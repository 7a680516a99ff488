#pragma once
/// Making written results durable before they are renamed into place: fsync of a file, of a
/// directory (its entries), or of a whole tree.

#include <string>

namespace cairn {

/// fsync the file at `path`; throws std::runtime_error naming it on failure
void sync_file(const std::string& path);

/// fsync the directory at `path` (its entries: creations and renames); throws std::runtime_error
void sync_dir(const std::string& path);

/// fsync every regular file and directory under `root`, and `root` itself
void sync_tree(const std::string& root);

}  // namespace cairn
