#include "scene/scene_io.hpp"

#include <fstream>
#include <sstream>

#include "error.hpp"
#include "scene/scene_limits.hpp"
#include "scene/scene_read.hpp"
#include "scene/toml_reader.hpp"

namespace cairn {

namespace {

std::string trim(const std::string& s) {
    auto b = s.find_first_not_of(" \t");
    if (b == std::string::npos) return {};
    auto e = s.find_last_not_of(" \t");
    return s.substr(b, e - b + 1);
}

// a TOML basic string holding `text`
std::string quoted(const std::string& text) {
    std::string out = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}

// refuse what the TOML parser must not see: control characters, invalid UTF-8, too many key
// parts, a value beyond the size or nesting limits
void check_override_text(const Override& o) {
    const std::string key = "--set " + printable(o.key);
    if (auto p = text_problem(o.key, false); !p.empty()) throw Error(key + ": the key contains " + p);
    if (auto p = text_problem(o.value, true); !p.empty())
        throw Error(key + " = " + printable(o.value) + ": the value contains " + p);
    int parts = 1;
    for (char c : o.key) parts += c == '.';
    if (parts > kMaxKeyParts)
        throw Error(key + ": a key of " + std::to_string(parts) + " parts, beyond the limit of " +
                    std::to_string(kMaxKeyParts));
    check_toml_limits(o.value, key);
}

// set the override into the document at its dotted path, creating tables on the way
void apply_override(toml::table& root, const Override& o, scene_detail::Sources& src) {
    check_override_text(o);
    const std::string origin = "--set " + o.key;
    // the value as TOML; if that fails, the text as a string
    std::string text = "v = " + o.value;
    toml::table parsed;
    try {
        parsed = toml::parse(text, std::string(origin));
    } catch (const toml::parse_error&) {
        text = "v = " + quoted(o.value);
        try {
            parsed = toml::parse(text, std::string(origin));
        } catch (const toml::parse_error& e) {
            throw Error(origin + " = " + printable(o.value) + ": not a TOML value nor a string: " +
                        std::string(e.description()));
        }
    }
    src.add(origin, text);

    std::vector<std::string> parts;
    std::stringstream ss(o.key);
    for (std::string part; std::getline(ss, part, '.');) parts.push_back(part);
    if (o.key.back() == '.') parts.push_back("");
    toml::table* t = &root;
    std::string path;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        if (parts[i].empty()) throw Error(origin + ": empty component in the key path");
        path += (path.empty() ? "" : ".") + parts[i];
        if (i + 1 == parts.size()) break;
        toml::node* next = t->get(parts[i]);
        if (!next) {
            t->insert(parts[i], toml::table{});
            next = t->get(parts[i]);
            src.add_created_table(next->as_table(), o.key);
        }
        if (!next->is_table())
            throw Error(origin + ": " + path + " is not a table, so " + o.key + " cannot be set");
        t = next->as_table();
    }
    t->insert_or_assign(parts.back(), std::move(*parsed.get("v")));
}

// a --set contact.scheme that switches the scheme drops the file's key of the other scheme
// (grid_spacing of "paper", subdivision of "overlap"), which would otherwise refuse the switch;
// the same key given by another --set is still checked against the scheme
void drop_other_scheme_keys(toml::table& root, const std::vector<Override>& overrides) {
    toml::table* contact = root["contact"].as_table();
    if (!contact) return;
    for (const auto& o : overrides) {
        if (o.key != "contact.scheme") continue;
        std::string v = o.value;
        if (v.size() >= 2 && (v.front() == '"' || v.front() == '\'') && v.back() == v.front())
            v = v.substr(1, v.size() - 2);
        if (v == "paper") contact->erase("subdivision");
        else if (v == "overlap") contact->erase("grid_spacing");
    }
}

}  // namespace

void apply_model(Scene& scene, const std::string& model) {
    if (model.empty()) return;
    BlockModel m;
    if (model == "rigid") m = BlockModel::rigid;
    else if (model == "deformable") m = BlockModel::deformable;
    else throw Error("--model " + model + ": expected rigid or deformable");
    for (auto& b : scene.blocks)
        if (!b.fixed) b.model = m;
}

Override parse_override(const std::string& text) {
    auto eq = text.find('=');
    if (eq == std::string::npos)
        throw Error("--set " + text + ": expected key=value");
    Override o{trim(text.substr(0, eq)), trim(text.substr(eq + 1))};
    if (o.key.empty()) throw Error("--set " + text + ": the key before '=' is empty");
    return o;
}

Scene load_scene(const std::string& path, const std::vector<Override>& overrides) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path + ": cannot open scene file");
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw Error(path + ": cannot read scene file");
    return parse_scene(text.str(), path, overrides);
}

Scene parse_scene(const std::string& toml_text, const std::string& source,
                  const std::vector<Override>& overrides) {
    check_toml_limits(toml_text, source);
    scene_detail::Sources src;
    src.add(source, toml_text);
    toml::table root;
    try {
        root = toml::parse(toml_text, std::string(source));
    } catch (const toml::parse_error& e) {
        const auto& at = e.source().begin;
        throw Error(source + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) +
                    ": TOML syntax error: " + std::string(e.description()));
    }
    drop_other_scheme_keys(root, overrides);
    for (const auto& o : overrides) apply_override(root, o, src);
    return scene_detail::read_scene(src, root, source);
}

}  // namespace cairn
