#pragma once
/// A reference kind as a strategy: everything the compare layer knows about one kind a scene's
/// [reference] may name. The table of kinds is case_kinds(), which every kind joins from its own
/// file (a KindRegistration there): a new kind is its file in compare/cases/ plus its name and
/// parameters in the loader's core/scene/reference_kinds.cpp, which a test checks against the table.

#include <string>
#include <vector>

#include "cases/case_analysis.hpp"

namespace cairn::cases {

/// One analytic reference kind.
class CaseKind {
public:
    virtual ~CaseKind() = default;
    /// the name a scene gives in [reference] kind, e.g. "housner"
    virtual std::string name() const = 0;
    /// the names of its optional numeric parameters (SI units; angles in rad)
    virtual std::vector<std::string> parameters() const = 0;
    /// metrics and figure data of one run of `scene` (its [reference] is of this kind)
    virtual CaseAnalysis analyse(const Scene& scene, const std::vector<Sample>& samples, ContactKind contact) const = 0;
    /// the reference curve at the given times (what analyse puts in `analytic`); empty: none
    virtual std::vector<double> curve(const Scene& scene, ContactKind contact, const std::vector<double>& t) const = 0;
    /// the contact modes of the reference engines ("rigid", "matched") whose runs of `scene` this
    /// kind can judge, in run order; dem's penalty contact is always judged
    virtual std::vector<std::string> contact_modes(const Scene& scene) const = 0;
    /// what CaseAnalysis::event_time marks, e.g. "first impact"
    virtual std::string event_label() const = 0;
    /// throws cairn::Error naming what of `scene` the kind's oracles cannot model; called before
    /// any run (validation::variants_for), so a scene they cannot judge fails before it is run
    virtual void check(const Scene& scene) const = 0;
};

/// A kind made of plain functions: how every kind in compare/cases is written.
class FunctionKind final : public CaseKind {
public:
    using Analyse = CaseAnalysis (*)(const Scene&, const std::vector<Sample>&, ContactKind);
    using Curve = std::vector<double> (*)(const Scene&, ContactKind, const std::vector<double>&);
    using Modes = std::vector<std::string> (*)(const Scene&);
    using Check = void (*)(const Scene&);
    /// `check` nullptr: the loader's checks are all the kind needs
    FunctionKind(std::string name, std::vector<std::string> parameters, Analyse analyse, Curve curve, Modes modes,
                 std::string event_label, Check check = nullptr);
    std::string name() const override { return name_; }
    std::vector<std::string> parameters() const override { return parameters_; }
    CaseAnalysis analyse(const Scene& scene, const std::vector<Sample>& samples, ContactKind contact) const override;
    std::vector<double> curve(const Scene& scene, ContactKind contact, const std::vector<double>& t) const override;
    std::vector<std::string> contact_modes(const Scene& scene) const override;
    std::string event_label() const override { return event_; }
    void check(const Scene& scene) const override;

private:
    std::string name_;
    std::vector<std::string> parameters_;
    Analyse analyse_;
    Curve curve_;   ///< nullptr: no reference curve
    Modes modes_;
    std::string event_;
    Check check_;
};

/// contact modes of a kind judged on rigid contact only (Coulomb friction, rigid pivots)
std::vector<std::string> rigid_contact_only(const Scene& scene);
/// contact modes of a kind whose reference is the penalty spring kn·A
std::vector<std::string> matched_contact_only(const Scene& scene);

/// Puts a kind in case_kinds() at start-up: `const KindRegistration r(my_kind);` in the kind's file
/// (compare/CMakeLists.txt links the files of compare/cases into every program, so none is dropped).
struct KindRegistration {
    /// `kind` returns the kind (a function-local static, built on first use)
    explicit KindRegistration(const CaseKind& (*kind)());
};

/// every registered kind, in the order of the loader's reference_kinds() (documentation order)
const std::vector<const CaseKind*>& case_kinds();

/// the kind named `name`; throws cairn::Error naming `source` (the scene file) when there is none
const CaseKind& case_kind(const std::string& name, const std::string& source);

}  // namespace cairn::cases
