#include "scene/scene_read.hpp"

#include <filesystem>

#include "error.hpp"
#include "scene/reference_kinds.hpp"

namespace cairn::scene_detail {

int block_named(const Item& item, const Scene& scene) {
    int b = scene.block_index(item.string());
    item.check(b >= 0, "no block of that name in [blocks]");
    return b;
}

TableReader sub_table(const TableReader& parent, const std::string& key,
                      const std::vector<std::string>& allowed) {
    Item it = parent.require(key);
    return TableReader(parent.sources(), it.table(), it.key(), allowed);
}

namespace {

// an empty table stands in for an absent optional section
const toml::table& empty_table() {
    static const toml::table t;
    return t;
}

TableReader optional_section(const TableReader& root, const std::string& key,
                             const std::vector<std::string>& allowed) {
    if (root.get(key)) return sub_table(root, key, allowed);
    return TableReader(root.sources(), empty_table(), key, allowed);
}

double positive(const Item& it) {
    double v = it.number();
    it.check(v > 0.0, "must be > 0");
    return v;
}

double non_negative(const Item& it) {
    double v = it.number();
    it.check(v >= 0.0, "must be >= 0");
    return v;
}

RunControl read_run(const TableReader& root) {
    TableReader r = sub_table(root, "run", {"duration", "dt", "dt_safety", "element_dt_safety",
                                            "output_interval", "contact_interval", "contact_margin", "settle"});
    RunControl rc;
    rc.duration = positive(r.require("duration"));
    if (Item it = r.get("dt")) {
        if (it.node().is_string()) it.check(it.string() == "auto", "expected a time step in s or \"auto\"");
        else rc.dt = positive(it);
    }
    if (Item it = r.get("dt_safety")) {
        rc.dt_safety = it.number();
        it.check(rc.dt_safety > 0.0 && rc.dt_safety <= 1.0, "must be in (0, 1]");
    }
    if (Item it = r.get("element_dt_safety")) {
        rc.element_dt_safety = it.number();
        it.check(rc.element_dt_safety > 0.0 && rc.element_dt_safety <= 1.0, "must be in (0, 1]");
    }
    if (Item it = r.get("output_interval")) rc.output_interval = positive(it);
    if (Item it = r.get("contact_interval")) {
        rc.contact_interval = it.small_integer();
        it.check(rc.contact_interval >= 1, "must be an integer >= 1");
    }
    if (Item it = r.get("contact_margin")) rc.contact_margin = positive(it);
    if (Item it = r.get("settle")) rc.settle = it.boolean();
    return rc;
}

void read_materials(const TableReader& root, Scene& scene) {
    TableReader all(root.sources(), root.require("materials").table(), "materials");
    for (auto&& [k, v] : all.table()) {
        const std::string name(k.str());
        TableReader m = sub_table(all, name, {"density", "young", "poisson"});
        Material mat;
        mat.name = name;
        mat.density = positive(m.require("density"));
        mat.young = positive(m.require("young"));
        Item nu = m.require("poisson");
        mat.poisson = nu.number();
        nu.check(mat.poisson > -1.0 && mat.poisson < 0.5, "must be in (-1, 0.5)");
        scene.materials.push_back(mat);
    }
}

ContactLaw read_contact(const TableReader& root) {
    TableReader c = sub_table(root, "contact", {"kn", "ks", "friction", "damping_ratio",
                                                "damping_time", "restitution", "grid_spacing",
                                                "scheme", "subdivision"});
    ContactLaw law;
    law.kn = positive(c.require("kn"));
    law.ks = law.kn;
    if (Item it = c.get("ks")) law.ks = non_negative(it);
    law.friction = non_negative(c.require("friction"));
    Item ratio = c.get("damping_ratio"), time = c.get("damping_time");
    if (ratio && time)
        time.fail("give damping_ratio or damping_time, not both");
    // a damping of 0 is no damping: every reader of the law (which engine modes a reference
    // judges, what the report says an engine cannot represent) then sees one undamped contact
    if (ratio) {
        law.damping_rule = ContactDampingRule::ratio;
        law.damping = ratio.number();
        ratio.check(law.damping >= 0.0 && law.damping < 1.0, "must be in [0, 1)");
    } else if (time) {
        law.damping_rule = ContactDampingRule::time;
        law.damping = non_negative(time);
    }
    if (law.damping == 0.0) law.damping_rule = ContactDampingRule::none;
    if (Item it = c.get("restitution")) {
        law.restitution = it.number();
        it.check(law.restitution >= 0.0 && law.restitution <= 1.0, "must be in [0, 1]");
    }
    if (Item it = c.get("scheme")) {
        const std::string s = it.string();
        if (s == "overlap") law.scheme = ContactScheme::overlap;
        else if (s == "paper") law.scheme = ContactScheme::paper;
        else it.fail("expected \"overlap\" or \"paper\"");
    }
    if (Item it = c.get("grid_spacing")) {
        law.grid_spacing = positive(it);
        it.check(law.scheme == ContactScheme::paper,
                 "applies to contact.scheme = \"paper\" only (the default is \"overlap\": set scheme = \"paper\" for the paper's grid of hitting points)");
    }
    if (Item it = c.get("subdivision")) {
        law.subdivision = it.small_integer();
        // n² sub-contacts per hitting face: bounded so that no scene can allocate without bound
        it.check(law.subdivision >= 1 && law.subdivision <= 16, "must be an integer in [1, 16]");
        it.check(law.scheme == ContactScheme::overlap, "applies to contact.scheme = \"overlap\" only");
    }
    return law;
}

Damping read_damping(const TableReader& root) {
    TableReader d = optional_section(root, "damping", {"alpha", "beta"});
    Damping damping;
    if (Item it = d.get("alpha")) damping.alpha = non_negative(it);
    if (Item it = d.get("beta")) damping.beta = non_negative(it);
    return damping;
}

void read_reference(const TableReader& root, Scene& scene) {
    Item section = root.get("reference");
    if (!section) return;
    TableReader any(root.sources(), section.table(), "reference");
    Item kind_item = any.require("kind");
    const ReferenceKind* kind = find_reference_kind(kind_item.string());
    if (!kind) {
        std::string list;
        for (const auto& k : reference_kinds()) list += (list.empty() ? "" : ", ") + k.name;
        kind_item.fail("unknown reference kind (known: " + list + ")");
    }
    std::vector<std::string> allowed = {"kind", "block"};
    allowed.insert(allowed.end(), kind->parameters.begin(), kind->parameters.end());
    TableReader r(root.sources(), section.table(), "reference", allowed);
    ReferenceDef ref;
    ref.kind = kind->name;
    Item block = r.require("block");
    ref.block = block_named(block, scene);
    block.check(!scene.blocks[static_cast<std::size_t>(ref.block)].fixed,
                "the reference describes a moving block; this one is fixed (the ground or a support)");
    for (const auto& p : kind->parameters)
        if (Item it = r.get(p)) ref.values[p] = it.number();
    scene.reference = ref;
}

void read_backends(const TableReader& root, Scene& scene) {
    Item section = root.get("backends");
    if (!section) return;
    TableReader all(root.sources(), section.table(), "backends");
    // any name is read here: the registry, which knows the backends built, rejects unknown ones
    for (auto&& [k, v] : all.table()) {
        const std::string name(k.str());
        Item it = all.get(name);
        auto& settings = scene.backend_settings[name];
        for (auto&& [sk, sv] : it.table()) {
            Item s(root.sources(), &sv, it.key() + "." + std::string(sk.str()));
            Setting setting;
            setting.origin = root.sources().origin(sv);
            if (auto b = sv.as_boolean()) setting.value = b->get();
            else if (auto i = sv.as_integer()) setting.value = i->get();
            else if (sv.is_floating_point()) setting.value = s.number();
            else if (auto str = sv.as_string()) setting.value = str->get();
            else s.fail("a backend setting must be a bool, integer, float or string");
            settings[std::string(sk.str())] = setting;
        }
    }
}

}  // namespace

Scene read_scene(const Sources& src, const toml::table& root_table, const std::string& source) {
    TableReader root(src, root_table, "",
                     {"name", "description", "gravity", "run", "materials", "contact", "damping",
                      "blocks", "loads", "ground_motion", "probes", "reference", "backends"});
    Scene scene;
    scene.source = source;
    scene.name = std::filesystem::path(source).stem().string();
    if (Item it = root.get("name")) {
        scene.name = it.string();
        it.check(!scene.name.empty(), "must not be empty");
    }
    if (Item it = root.get("description")) scene.description = it.string();
    if (Item it = root.get("gravity")) scene.gravity = it.vec3();
    scene.run = read_run(root);
    read_materials(root, scene);
    scene.contact = read_contact(root);
    scene.damping = read_damping(root);
    read_blocks(root, scene);
    check_overlaps(root, scene);
    read_loads(root, scene);
    read_ground_motion(root, scene);
    read_probes(root, scene);
    read_reference(root, scene);
    read_backends(root, scene);
    return scene;
}

}  // namespace cairn::scene_detail
