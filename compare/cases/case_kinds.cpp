// the table of reference kinds: each kind registers itself from its own file
#include <algorithm>

#include "cases/case_kind.hpp"
#include "cases/upright_frames.hpp"
#include "error.hpp"
#include "scene/reference_kinds.hpp"

namespace cairn::cases {

namespace {

/// the kinds registered so far (a function-local static: ready before any registration runs)
std::vector<const CaseKind& (*)()>& registered() {
    static std::vector<const CaseKind& (*)()> kinds;
    return kinds;
}

/// a kind's place: its index in the loader's list, then unknown names after them by name
std::pair<size_t, std::string> rank(const CaseKind* k) {
    const auto& names = reference_kinds();
    const auto it = std::find_if(names.begin(), names.end(), [&](const ReferenceKind& r) { return r.name == k->name(); });
    return {size_t(it - names.begin()), k->name()};
}

}  // namespace

KindRegistration::KindRegistration(const CaseKind& (*kind)()) { registered().push_back(kind); }

const std::vector<const CaseKind*>& case_kinds() {
    static const std::vector<const CaseKind*> kinds = [] {
        std::vector<const CaseKind*> k;
        for (auto* f : registered()) k.push_back(&f());
        std::sort(k.begin(), k.end(), [](const CaseKind* a, const CaseKind* b) { return rank(a) < rank(b); });
        return k;
    }();
    return kinds;
}

FunctionKind::FunctionKind(std::string name, std::vector<std::string> parameters, Analyse analyse, Curve curve,
                           Modes modes, std::string event_label, Check check)
    : name_(std::move(name)), parameters_(std::move(parameters)), analyse_(analyse), curve_(curve), modes_(modes),
      event_(std::move(event_label)), check_(check) {}

namespace {

/// the variant's contact with the reference block's divisions renamed as upright_frames renames its axes
ContactKind upright_contact(const Scene& scene, ContactKind contact) {
    if (scene.reference) contact.divisions = upright_divisions(scene, scene.reference->block, contact.divisions);
    return contact;
}

}  // namespace

// every kind sees the scene in upright frames (upright_frames.hpp): a box's frame z is its height
CaseAnalysis FunctionKind::analyse(const Scene& scene, const std::vector<Sample>& samples, ContactKind contact) const {
    return analyse_(upright_frames(scene), upright_samples(scene, samples), upright_contact(scene, contact));
}

std::vector<double> FunctionKind::curve(const Scene& scene, ContactKind contact, const std::vector<double>& t) const {
    return curve_ ? curve_(upright_frames(scene), upright_contact(scene, contact), t) : std::vector<double>{};
}

std::vector<std::string> FunctionKind::contact_modes(const Scene& scene) const { return modes_(upright_frames(scene)); }

void FunctionKind::check(const Scene& scene) const {
    if (check_) check_(upright_frames(scene));
}

std::vector<std::string> rigid_contact_only(const Scene&) { return {"rigid"}; }
std::vector<std::string> matched_contact_only(const Scene&) { return {"matched"}; }

const CaseKind& case_kind(const std::string& name, const std::string& source) {
    for (const CaseKind* k : case_kinds())
        if (k->name() == name) return *k;
    throw Error(source + ": reference kind '" + name + "' has no validation metrics (compare/cases)");
}

}  // namespace cairn::cases
