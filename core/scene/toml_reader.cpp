#include "scene/toml_reader.hpp"

#include <cmath>
#include <limits>
#include <sstream>

#include "error.hpp"

namespace cairn::scene_detail {

void Sources::add(const std::string& path, std::string text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    lines_[path] = std::move(lines);
}

void Sources::add_created_table(const toml::table* table, const std::string& override_key) {
    created_[table] = override_key;
}

std::string Sources::origin(const toml::node& node) const {
    const auto& region = node.source();
    if (!region.path) {
        // a table made by --set carries no source of its own
        if (auto t = node.as_table()) {
            auto it = created_.find(t);
            if (it != created_.end()) return "--set " + it->second;
        }
        return "--set";
    }
    const std::string& path = *region.path;
    if (path.rfind("--set ", 0) == 0) return path;
    if (region.begin.line == 0) return path;
    return path + ":" + std::to_string(region.begin.line);
}

std::string Sources::written(const toml::node& node) const {
    if (auto t = node.as_table(); t && !t->is_inline()) return "(table)";
    const auto& region = node.source();
    auto it = region.path ? lines_.find(*region.path) : lines_.end();
    if (it == lines_.end() || region.begin.line == 0 || region.end.line < region.begin.line) {
        // no source text (a value built here): print it the TOML way
        std::ostringstream out;
        node.visit([&](auto&& v) { out << toml::toml_formatter{v}; });
        return out.str();
    }
    const auto& lines = it->second;
    std::string text;
    for (auto l = region.begin.line; l <= region.end.line && l <= lines.size(); ++l) {
        const std::string& line = lines[l - 1];
        std::size_t from = (l == region.begin.line) ? region.begin.column - 1 : 0;
        std::size_t to = (l == region.end.line) ? region.end.column - 1 : line.size();
        from = std::min(from, line.size());
        to = std::min(std::max(to, from), line.size());
        if (!text.empty()) text += ' ';
        text += line.substr(from, to - from);
    }
    // collapse the runs of blanks a multi-line array leaves
    std::string out;
    for (char c : text) {
        bool blank = (c == ' ' || c == '\t' || c == '\r');
        if (blank && !out.empty() && out.back() == ' ') continue;
        out += blank ? ' ' : c;
    }
    while (!out.empty() && out.back() == ' ') out.pop_back();
    return out;
}

namespace {

/// an array or table longer than this many characters is quoted by its start only
constexpr std::size_t kQuoteMax = 120;
/// any other value (a string, a path) longer than this, likewise
constexpr std::size_t kQuoteScalarMax = 400;

/// the value as written, its start only when long: "[0, 0.1, 0.2, … (202 elements)]"
std::string quoted(const toml::node& node, std::string text) {
    const bool compound = node.is_array() || node.is_table();
    const std::size_t max = compound ? kQuoteMax : kQuoteScalarMax;
    if (text.size() <= max) return text;
    std::size_t cut = compound ? text.rfind(", ", max - 20) : std::string::npos;
    if (cut == std::string::npos || cut == 0) cut = max - 20;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;   // not inside a UTF-8 character
    text.resize(cut);
    if (auto a = node.as_array()) return text + ", … (" + std::to_string(a->size()) + " elements)]";
    return text + " …";
}

}  // namespace

void fail_at(const Sources& src, const toml::node& node, const std::string& key,
             const std::string& what) {
    throw Error(src.origin(node) + ": " + key + " = " + quoted(node, src.written(node)) + ": " + what);
}

// ---------------------------------------------------------------- Item

double Item::number() const {
    double v;
    if (auto i = node_->as_integer()) v = static_cast<double>(i->get());
    else if (auto f = node_->as_floating_point()) v = f->get();
    else fail("expected a number");
    check(std::isfinite(v), "must be a finite number");
    return v;
}

long long Item::integer() const {
    if (auto i = node_->as_integer()) return i->get();
    fail(node_->is_floating_point() ? "expected an integer, not a float" : "expected an integer");
}

int Item::small_integer() const {
    long long v = integer();
    check(v >= std::numeric_limits<int>::min() && v <= std::numeric_limits<int>::max(),
          "integer out of range");
    return static_cast<int>(v);
}

bool Item::boolean() const {
    if (auto b = node_->as_boolean()) return b->get();
    fail("expected true or false");
}

std::string Item::string() const {
    if (auto s = node_->as_string()) return s->get();
    fail("expected a string");
}

const toml::table& Item::table() const {
    if (auto t = node_->as_table()) return *t;
    fail("expected a table");
}

const toml::array& Item::array() const {
    if (auto a = node_->as_array()) return *a;
    fail("expected an array");
}

Item Item::element(std::size_t i) const {
    return Item(*src_, array().get(i), key_ + "[" + std::to_string(i) + "]");
}

std::vector<double> Item::numbers(std::size_t n) const {
    const std::string what = "expected an array of " + std::to_string(n) + " numbers";
    auto a = node_->as_array();
    check(a && a->size() == n, what);
    std::vector<double> out;
    for (const auto& e : *a) {
        if (!e.is_integer() && !e.is_floating_point()) fail(what);
        double v = e.is_integer() ? static_cast<double>(e.as_integer()->get())
                                  : e.as_floating_point()->get();
        check(std::isfinite(v), "every component must be a finite number");
        out.push_back(v);
    }
    return out;
}

Vec3 Item::vec3() const {
    auto v = numbers(3);
    return Vec3(v[0], v[1], v[2]);
}

std::vector<long long> Item::integers() const {
    auto a = node_->as_array();
    check(a != nullptr, "expected an array of integers");
    std::vector<long long> out;
    for (const auto& e : *a) {
        if (!e.is_integer())
            fail(e.is_floating_point() ? "expected an array of integers, found a float"
                                       : "expected an array of integers");
        out.push_back(e.as_integer()->get());
    }
    return out;
}

TableReader Item::reader(const std::vector<std::string>& allowed) const {
    return TableReader(*src_, table(), key_, allowed);
}

// ---------------------------------------------------------------- TableReader

TableReader::TableReader(const Sources& src, const toml::table& table, std::string path,
                         const std::vector<std::string>& allowed)
    : src_(&src), table_(&table), path_(std::move(path)) {
    for (auto&& [k, v] : table) {
        bool ok = false;
        for (const auto& a : allowed) ok = ok || (k.str() == a);
        if (ok) continue;
        std::string list;
        for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
        fail_at(src, v, path_of(std::string(k.str())),
                "unknown key" + (list.empty() ? std::string(" (this table takes no keys)")
                                              : " (allowed: " + list + ")"));
    }
}

TableReader::TableReader(const Sources& src, const toml::table& table, std::string path)
    : src_(&src), table_(&table), path_(std::move(path)) {}

Item TableReader::get(const std::string& key) const {
    return Item(*src_, table_->get(key), path_of(key));
}

Item TableReader::require(const std::string& key) const {
    const toml::node* n = table_->get(key);
    if (!n) throw Error(src_->origin(*table_) + ": " + path_of(key) + ": missing required key");
    return Item(*src_, n, path_of(key));
}

std::string TableReader::path_of(const std::string& key) const {
    return path_.empty() ? key : path_ + "." + key;
}

Item TableReader::self() const { return Item(*src_, table_, path_); }

}  // namespace cairn::scene_detail
