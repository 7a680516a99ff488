#include "scene/scene_limits.hpp"

#include <algorithm>
#include <cstdio>

#include "error.hpp"

namespace cairn {

namespace {

// the start of line `line` (1-based) of `text`, at most 60 characters, for messages
std::string line_excerpt(const std::string& text, std::size_t line_start) {
    std::size_t end = text.find('\n', line_start);
    if (end == std::string::npos) end = text.size();
    const std::size_t n = std::min<std::size_t>(end - line_start, 60);
    return printable(text.substr(line_start, n)) + (end - line_start > n ? "..." : "");
}

// length of the UTF-8 sequence starting at s[i], or 0 if it is not a valid one
std::size_t utf8_length(const std::string& s, std::size_t i) {
    const auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
    const unsigned c = b(i);
    std::size_t n;
    unsigned min;
    if (c < 0x80) return 1;
    if ((c & 0xE0) == 0xC0) n = 2, min = 0x80;
    else if ((c & 0xF0) == 0xE0) n = 3, min = 0x800;
    else if ((c & 0xF8) == 0xF0) n = 4, min = 0x10000;
    else return 0;
    if (i + n > s.size()) return 0;
    unsigned cp = c & (0x7F >> n);
    for (std::size_t k = 1; k < n; ++k) {
        if ((b(i + k) & 0xC0) != 0x80) return 0;
        cp = (cp << 6) | (b(i + k) & 0x3F);
    }
    // no overlong forms, surrogates or code points beyond U+10FFFF
    if (cp < min || (cp >= 0xD800 && cp <= 0xDFFF) || cp > 0x10FFFF) return 0;
    return n;
}

std::string hex_byte(unsigned char c) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "0x%02x", c);
    return buf;
}

}  // namespace

void check_toml_limits(const std::string& text, const std::string& source) {
    if (text.size() > kMaxSceneBytes)
        throw Error(source + ": " + std::to_string(text.size()) + " bytes, beyond the limit of " +
                    std::to_string(kMaxSceneBytes) + " bytes (16 MiB) for a scene");
    // a small lexer: strings and comments are skipped; brackets nest; dots between separators
    // count the parts of a dotted key (a number has at most one dot)
    std::size_t line = 1, line_start = 0;
    int depth = 0, dots = 0;
    auto fail = [&](const std::string& what) {
        throw Error(source + ":" + std::to_string(line) + ": " + line_excerpt(text, line_start) + ": " + what);
    };
    auto newline = [&](std::size_t i) {
        ++line;
        line_start = i + 1;
    };
    const std::size_t n = text.size();
    for (std::size_t i = 0; i < n; ++i) {
        const char c = text[i];
        if (c == '\n') {
            newline(i);
            dots = 0;
        } else if (c == '#') {
            while (i + 1 < n && text[i + 1] != '\n') ++i;
        } else if (c == '"' || c == '\'') {
            const bool multi = text.compare(i, 3, std::string(3, c)) == 0;
            const bool escapes = c == '"';
            i += multi ? 3 : 1;
            for (; i < n; ++i) {
                if (text[i] == '\n') {
                    if (!multi) break;   // the parser reports the unterminated string
                    newline(i);
                } else if (escapes && text[i] == '\\') {
                    if (i + 1 < n && text[i + 1] == '\n') newline(i + 1);
                    ++i;
                } else if (text[i] == c && (!multi || text.compare(i, 3, std::string(3, c)) == 0)) {
                    if (multi) i += 2;
                    break;
                }
            }
            if (i < n && text[i] == '\n') newline(i), dots = 0;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxNesting)
                fail("arrays, inline tables and table headers nested deeper than " +
                     std::to_string(kMaxNesting) + " levels (the limit of a scene)");
            dots = 0;
        } else if (c == ']' || c == '}') {
            depth = depth > 0 ? depth - 1 : 0;
            dots = 0;
        } else if (c == ',' || c == '=') {
            dots = 0;
        } else if (c == '.') {
            if (++dots + 1 > kMaxKeyParts)
                fail("a dotted key or table header of more than " + std::to_string(kMaxKeyParts) +
                     " parts (the limit of a scene)");
        }
    }
}

std::string text_problem(const std::string& text, bool allow_tab) {
    for (std::size_t i = 0; i < text.size();) {
        const auto c = static_cast<unsigned char>(text[i]);
        if ((c < 0x20 && !(allow_tab && c == '\t')) || c == 0x7F)
            return "a control character (" + hex_byte(c) + ")";
        const std::size_t len = utf8_length(text, i);
        if (len == 0) return "invalid UTF-8 at byte " + std::to_string(i) + " (" + hex_byte(c) + ")";
        i += len;
    }
    return {};
}

std::string printable(const std::string& text) {
    std::string out;
    for (std::size_t i = 0; i < text.size();) {
        const auto c = static_cast<unsigned char>(text[i]);
        const std::size_t len = utf8_length(text, i);
        if (len == 0 || c < 0x20 || c == 0x7F) {
            out += "\\x" + hex_byte(c).substr(2);
            ++i;
        } else {
            out.append(text, i, len);
            i += len;
        }
    }
    return out;
}

std::string column_name_problem(const std::string& name) {
    if (name.empty()) return "a name must not be empty";
    if (auto p = text_problem(name, false); !p.empty()) return "a name must not contain " + p;
    if (name.find(',') != std::string::npos) return "a name must not contain ',' (it becomes a CSV column name)";
    if (name.find('"') != std::string::npos) return "a name must not contain '\"' (it becomes a CSV column name)";
    return {};
}

}  // namespace cairn
