#pragma once
/// Internal to the scene loader: typed, checked reading of a toml++ document with messages
/// "<origin>: <dotted.key> = <value as written>: <what is wrong>". Not part of the public API
/// (it exposes toml++, which only core links).

#include <initializer_list>
#include <map>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "geometry/types.hpp"

namespace cairn::scene_detail {

/// The texts a document was assembled from (the file and each --set value), to quote values as
/// written and to say where they came from.
class Sources {
public:
    /// register a source text under the path its toml++ nodes carry
    void add(const std::string& path, std::string text);
    /// remember that `table` was created by the override `--set key`
    void add_created_table(const toml::table* table, const std::string& override_key);
    /// "file:line" for a file node, "--set key" for an overridden one
    std::string origin(const toml::node& node) const;
    /// the node's text as written in its source (a table that is not inline: "(table)")
    std::string written(const toml::node& node) const;

private:
    std::map<std::string, std::vector<std::string>> lines_;   // source path → its lines
    std::map<const toml::table*, std::string> created_;       // tables made by --set
};

/// "<origin>: <key> = <value>: <what>" as a cairn::Error
[[noreturn]] void fail_at(const Sources& src, const toml::node& node, const std::string& key,
                          const std::string& what);

/// One value of the document, with its dotted key; empty when the key is absent.
class Item {
public:
    Item(const Sources& src, const toml::node* node, std::string key)
        : src_(&src), node_(node), key_(std::move(key)) {}
    explicit operator bool() const { return node_ != nullptr; }
    const std::string& key() const { return key_; }
    const toml::node& node() const { return *node_; }
    const Sources& sources() const { return *src_; }
    /// this item as a table whose keys must all be in `allowed`
    class TableReader reader(const std::vector<std::string>& allowed) const;
    /// throw the standard message about this value
    [[noreturn]] void fail(const std::string& what) const { fail_at(*src_, *node_, key_, what); }
    /// fail unless ok
    void check(bool ok, const std::string& what) const { if (!ok) fail(what); }

    double number() const;                  ///< a finite number (integer or float)
    long long integer() const;              ///< an integer (a float is an error)
    int small_integer() const;              ///< an integer that fits an int
    bool boolean() const;                   ///< true or false
    std::string string() const;             ///< a string
    Vec3 vec3() const;                      ///< an array of 3 finite numbers
    std::vector<double> numbers(std::size_t n) const;   ///< an array of exactly n finite numbers
    std::vector<long long> integers() const;            ///< an array of integers
    const toml::table& table() const;       ///< a table (inline or not)
    const toml::array& array() const;       ///< an array
    /// element i of an array, keyed "key[i]"
    Item element(std::size_t i) const;

private:
    const Sources* src_;
    const toml::node* node_;
    std::string key_;
};

/// A table whose keys are all checked: a key outside the allowed set is an error at construction.
class TableReader {
public:
    /// `path` is the dotted path of the table ("" for the root); `allowed` lists its keys
    TableReader(const Sources& src, const toml::table& table, std::string path,
                const std::vector<std::string>& allowed);
    /// a table whose keys are free names (e.g. [blocks]): no key check
    TableReader(const Sources& src, const toml::table& table, std::string path);

    /// the value of `key`, empty if absent
    Item get(const std::string& key) const;
    /// the value of `key`; error "missing required key" at the table's line if absent
    Item require(const std::string& key) const;
    /// the dotted path of a key of this table
    std::string path_of(const std::string& key) const;
    /// this table as an item (for messages about the table itself)
    Item self() const;
    const toml::table& table() const { return *table_; }
    const Sources& sources() const { return *src_; }

private:
    const Sources* src_;
    const toml::table* table_;
    std::string path_;
};

}  // namespace cairn::scene_detail
