// the table of reference kinds: one line per kind (each defined in its own file)
#include "cases/case_kind.hpp"
#include "error.hpp"

namespace cairn::cases {

const CaseKind& rest_kind();
const CaseKind& impact_kind();
const CaseKind& slide_kind();
const CaseKind& stick_kind();
const CaseKind& incline_kind();
const CaseKind& rolling_kind();
const CaseKind& housner_kind();
const CaseKind& pushover_kind();
const CaseKind& arch_kind();

const std::vector<const CaseKind*>& case_kinds() {
    static const std::vector<const CaseKind*> kinds = {
        &rest_kind(), &impact_kind(), &slide_kind(), &stick_kind(), &incline_kind(),
        &rolling_kind(), &housner_kind(), &pushover_kind(), &arch_kind(),
    };
    return kinds;
}

FunctionKind::FunctionKind(std::string name, std::vector<std::string> parameters, Analyse analyse, Curve curve,
                           Modes modes, std::string event_label)
    : name_(std::move(name)), parameters_(std::move(parameters)), analyse_(analyse), curve_(curve), modes_(modes),
      event_(std::move(event_label)) {}

CaseAnalysis FunctionKind::analyse(const Scene& scene, const std::vector<Sample>& samples, ContactKind contact) const {
    return analyse_(scene, samples, contact);
}

std::vector<double> FunctionKind::curve(const Scene& scene, ContactKind contact, const std::vector<double>& t) const {
    return curve_ ? curve_(scene, contact, t) : std::vector<double>{};
}

std::vector<std::string> rigid_contact_only(const Scene&) { return {"rigid"}; }
std::vector<std::string> matched_contact_only(const Scene&) { return {"matched"}; }

const CaseKind& case_kind(const std::string& name, const std::string& source) {
    for (const CaseKind* k : case_kinds())
        if (k->name() == name) return *k;
    throw Error(source + ": reference kind '" + name + "' has no validation metrics (compare/cases)");
}

}  // namespace cairn::cases
