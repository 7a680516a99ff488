#include <algorithm>
#include <cmath>

#include "scene/scene_io.hpp"

namespace cairn {

namespace {

nlohmann::json vec(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

nlohmann::json block_json(const BlockDef& b, const Scene& scene) {
    nlohmann::json corners = nlohmann::json::array();
    for (const auto& c : b.corners) corners.push_back(vec(c));
    const auto& q = b.orientation;
    nlohmann::json j = {
        {"name", b.name},
        {"shape", to_string(b.shape)},
        {"corners", corners},
        {"position", vec(b.position)},
        {"orientation", {q.w(), q.x(), q.y(), q.z()}},
        {"velocity", vec(b.velocity)},
        {"angular_velocity", vec(b.angular_velocity)},
        {"material", scene.materials.at(static_cast<std::size_t>(b.material)).name},
        {"fixed", b.fixed},
        {"model", to_string(b.model)},
        {"mesh",
         {{"divisions", b.mesh.divisions},
          {"mass", to_string(b.mesh.mass)},
          {"fix_base", b.mesh.fix_base},
          {"fixed_nodes", b.mesh.fixed_nodes}}},
    };
    if (b.shape == Shape::box) j["size"] = vec(b.size);
    return j;
}

}  // namespace

nlohmann::json scene_to_json(const Scene& scene) {
    using nlohmann::json;
    auto block_name = [&](int i) { return scene.blocks.at(static_cast<std::size_t>(i)).name; };

    json materials = json::array();
    for (const auto& m : scene.materials)
        materials.push_back({{"name", m.name}, {"density", m.density}, {"young", m.young},
                             {"poisson", m.poisson}});
    const auto& c = scene.contact;
    json contact = {{"kn", c.kn}, {"ks", c.ks}, {"friction", c.friction},
                    {"damping_rule", to_string(c.damping_rule)}, {"damping", c.damping},
                    {"restitution", c.restitution}, {"scheme", to_string(c.scheme)}};
    if (c.scheme == ContactScheme::paper) contact["grid_spacing"] = c.grid_spacing;
    else contact["subdivision"] = c.subdivision;
    json blocks = json::array();
    for (const auto& b : scene.blocks) blocks.push_back(block_json(b, scene));
    json loads = json::array();
    for (const auto& l : scene.loads)
        if (!l.history)
            loads.push_back({{"block", block_name(l.block)}, {"force", vec(l.force)},
                             {"point", vec(l.point)}, {"ramp", l.ramp}, {"start", l.start}});
    json ground = nullptr;
    if (const auto& g = scene.ground_motion) {
        // one entry per component; the first one's fields also at the top (older readers)
        json components = json::array();
        for (const GroundComponent& c : g->components) {
            double peak = 0.0;
            for (double a : c.acceleration.value) peak = std::max(peak, std::abs(a));
            components.push_back({{"source", c.source}, {"direction", vec(c.direction)},
                                  {"samples", c.acceleration.time.size()},
                                  {"duration", c.acceleration.time.back() - c.acceleration.time.front()},
                                  {"peak_acceleration", peak}});
        }
        ground = components.front();
        ground["start"] = g->start;
        ground["components"] = components;
    }
    json probes = json::array();
    for (const auto& p : scene.probes)
        probes.push_back({{"name", p.name}, {"block", block_name(p.block)}, {"point", vec(p.point)}});
    const auto& r = scene.run;
    json run = {{"duration", r.duration},
                {"dt", r.dt ? json(*r.dt) : json("auto")},
                {"dt_safety", r.dt_safety},
                {"element_dt_safety", r.element_dt_safety},
                {"output_interval", r.output_interval},
                {"contact_interval", r.contact_interval},
                {"contact_margin", r.contact_margin ? json(*r.contact_margin) : json("auto")},
                {"settle", r.settle}};
    json reference = nullptr;
    if (scene.reference) {
        reference = {{"kind", scene.reference->kind}, {"values", scene.reference->values}};
        if (scene.reference->block >= 0) reference["block"] = block_name(scene.reference->block);
    }
    json backends = json::object();
    for (const auto& [name, settings] : scene.backend_settings) {
        json t = json::object();
        for (const auto& entry : settings) {   // no structured binding: C++17 lambdas cannot capture one
            const auto& key = entry.first;
            const auto& origin = entry.second.origin;
            std::visit([&](const auto& v) { t[key] = {{"value", v}, {"origin", origin}}; }, entry.second.value);
        }
        backends[name] = t;
    }
    return {{"name", scene.name},
            {"description", scene.description},
            {"source", scene.source},
            {"gravity", vec(scene.gravity)},
            {"run", run},
            {"materials", materials},
            {"contact", contact},
            {"damping", {{"alpha", scene.damping.alpha}, {"beta", scene.damping.beta}}},
            {"blocks", blocks},
            {"loads", loads},
            {"ground_motion", ground},
            {"probes", probes},
            {"reference", reference},
            {"backends", backends}};
}

}  // namespace cairn
