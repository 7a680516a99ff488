// the report document of a validation (report.md and index.html are its two renderings)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include "report/miss_causes.hpp"
#include "report/text.hpp"
#include "report/validation_report.hpp"

namespace cairn::report {

using validation::CaseResult;
using validation::CaseRun;

namespace {

std::vector<std::string> conventions() {
    return {
        "Contact damping: the paper's \"contact damping 0.1 / 0.2 / 0.4\" is read as the damping ratio ζ of "
        "the contact spring (scene key contact.damping_ratio). Each hitting point of tributary area a gets "
        "the dashpot c = 2ζ·a·√(kn·m_red/A_face), which sums to 2ζ√(K m) for a face on a face (K = kn·A, "
        "m_red the pair's reduced mass). contact.damping_time = γ would give c = γ·kn·a instead.",
        "The normal contact force never pulls: a contact releases when spring + dashpot reach zero. The "
        "impact oracle integrates exactly that 1-DOF contact phase with gravity (restitution 0.720 at "
        "ζ = 0.1, 0.527 at 0.2, 0.281 at 0.4; not the tension-allowed exp(−ζπ/√(1−ζ²))).",
        "Rocking: reading B (block 0.7 × 0.2 × 1.0 m rocking about a 0.2 m edge, θ0 = 30°); rocking_slender "
        "and rocking_housner rock about the 0.7 m edge from θ0 = 0.8α. Each variant is judged against the "
        "reference that models its contact: rigid-contact runs against Housner's inelastic impact (velocity "
        "ratio 1 − 1.5 sin²α); dem's point springs (undamped or with a damping ratio) against the spring "
        "block, a planar rigid block on the same rows of hitting points with the same elastic–Coulomb law "
        "and dashpots, integrated independently at T/1000 (a penalty contact is not lossless: the block "
        "bounces and sways on the springs and its edge slips at impact); an engine's matched contact only "
        "on the first impact (after it, no reference models the engine's impact: not comparable). The half "
        "cycle is judged as 2·t1(θ1) with the measured θ1 (rigid contact), or as the spring block's own half "
        "cycle carried to the measured θ1 by the ratio of those 2·t1 (dem). rocking_housner's contact damping ζ = 0.386 is "
        "calibrated so that the spring block loses what Housner's impact loses: dem is also judged on "
        "Housner's amplitudes after three impacts. It takes a slender block and kn ≤ ~1e8 (ζ grows with kn: 0.30 at "
        "1e7, 0.70 at 1e8); for reading B (α = 35°) no damping ratio comes within a factor 2 of Housner's loss "
        "(docs/validation.md).",
        "friction_stick: H at the centroid lifts the heel (e = H·h/W > B/6): the reference is a rigid block on "
        "a Winkler base whose lightly pressed points slip, u = (μ kn/ks)·d_max·[1 − √(1 − H/(μW))] (1.894 H/(ks·A)), "
        "loaded quasi-statically (8 s ramp, contact damping ratio 0.5); friction_stick_base applies H at the "
        "base: u = H/(ks·A) exactly.",
        "Verdicts: pass (within the tolerance), miss (outside it: the run does not do what the reference "
        "says), not comparable (the reference does not model what the variant does; the reason is given), "
        "info (reported, not judged).",
        "Variants: dem-rigid = in-house DEM with rigid blocks; dem-deformable = every free block deformable, "
        "meshed as the scene's [blocks.A.mesh] says (2 × 2 × 2 hex8, consistent mass in the paper scenes); "
        "<engine>-rigid = the engine's own rigid contact; <engine>-matched = contact matched to the "
        "penalty law (docs/backends.md). The reference engines step at 1e-4 s (dt = auto).",
        "Tolerances are the same for every backend: stability 1 % "
        "(penetration, period); impact 1 % (first contact, bounce period) and 2 % (peak penetration, "
        "rebound); sliding 1 %; Housner first impact 1 % for rigid contact and 2 % for penalty contact "
        "(edge on a face at the paper's kn); rolling: coarse oracles (10 %, bounds). A miss is reported, "
        "never hidden.",
        "Siconos (siconos-rigid) on the structure cases (validate --cases structures/...): arch_thick, "
        "arch_thin and column_pushover were run to their end on it and pass (column a/g −0.045 %); the "
        "wall pushover's 36 s ramp was not: its nonsmooth Gauss-Seidel solve takes ~78 iterations a step on "
        "the wall's 18 bricks, ~217 CPU s per simulated second (61× Bullet), ~2.2 h for the case on one "
        "idle core, and its cost grows as N² in the free blocks (docs/backends.md). It runs if asked; "
        "it is not refused.",
        "Penetration and heights are measured on node10 (a top corner of A, the paper's tracked node); "
        "rocking angles from A's orientation about the reference axis.",
    };
}

std::string reference_text(const Scene& s) {
    if (!s.reference) return "none";
    std::string t = s.reference->kind;
    for (const auto& [k, v] : s.reference->values) t += ", " + k + " = " + number_text(v);
    char b[200];
    std::snprintf(b, sizeof b, "; kn = %g N/m³, μ = %g, contact damping %s %g, mass damping α = %g 1/s, duration %g s",
                  s.contact.kn, s.contact.friction, to_string(s.contact.damping_rule), s.contact.damping,
                  s.damping.alpha, s.run.duration);
    return t + b;
}

/// legend of the case's analytic curve (from its first analysed run)
std::string analytic_label(const CaseResult& c) {
    for (const auto& r : c.runs)
        if (r.analysed) return r.analysis.analytic.empty() ? "no analytic curve" : r.analysis.analytic_label;
    return "no analytic curve";
}

}  // namespace

Document build_report(const std::vector<CaseResult>& cases, const FigureSet& figures, const ReportContext& ctx) {
    Document d;
    d.title = "cairn validation report";
    int runs = 0, passed = 0, missed = 0, nc = 0, other = 0;
    int m_pass = 0, m_miss = 0, m_nc = 0;
    for (const auto& c : cases)
        for (const auto& r : c.runs) {
            ++runs;
            const std::string v = verdict_cell(r);
            if (v.rfind("pass", 0) == 0) ++passed;
            else if (v.rfind("miss", 0) == 0) ++missed;
            else if (v == "n.c.") ++nc;
            else ++other;
            if (r.analysed)
                for (const auto& m : r.analysis.metrics) {
                    if (m.check == metrics::Check::not_comparable) ++m_nc;
                    else if (m.judged()) ++(m.pass() ? m_pass : m_miss);
                }
        }
    d.paragraph(std::to_string(cases.size()) + " cases, " + std::to_string(runs) + " runs: " + std::to_string(passed) +
                " pass, " + std::to_string(missed) + " miss, " + std::to_string(nc) + " not comparable, " +
                std::to_string(other) + " without metrics (cannot represent, failed). Metrics: " + std::to_string(m_pass) +
                " pass, " + std::to_string(m_miss) + " miss, " + std::to_string(m_nc) + " not comparable. " +
                fixed_text(ctx.wall_seconds, 1) + " s wall on " + std::to_string(ctx.jobs) + " threads. Command: " + ctx.command);
    if (!figures.note.empty()) d.paragraph("Figures: " + figures.note);
    d.contents();   // links to every section and case below, the verdict grid first

    // the grid: cases down, variants across (in order of first appearance), each cell links to its case
    d.heading(2, "Verdict");
    d.paragraph("pass: every judged metric within its tolerance; miss: at least one is not; n.c. (not comparable): "
                "no reference models what the variant does, counted in brackets beside the judged verdict (the reason "
                "is in the case's metric table).");
    std::vector<std::string> variants;
    for (const auto& c : cases)
        for (const auto& r : c.runs)
            if (std::find(variants.begin(), variants.end(), r.variant.name) == variants.end()) variants.push_back(r.variant.name);
    Table grid{{"case"}, {}, {}};
    for (const auto& v : variants) grid.header.push_back(v);
    for (const auto& c : cases) {
        std::vector<std::string> row{c.name}, links{c.name};
        for (const auto& v : variants) {
            std::string cell = "", link = "";
            for (const auto& r : c.runs)
                if (r.variant.name == v) cell = verdict_cell(r), link = c.name;
            row.push_back(cell);
            links.push_back(link);
        }
        grid.rows.push_back(row);
        grid.links.push_back(links);
    }
    d.table(grid);

    d.heading(3, "Runs");
    Table v{{"case", "variant", "verdict", "worst metric (value vs reference, error, tolerance)", "wall s"}, {}, {}};
    for (const auto& c : cases)
        for (const auto& r : c.runs) {
            const std::string worst_text = worst_metric_text(r);
            v.rows.push_back({c.name, r.variant.name, run_verdict(r), worst_text,
                              r.outcome == Outcome::refused ? "" : fixed_text(r.wall_seconds, 2)});
        }
    d.table(v);

    // every missed metric with the engine limitation that explains it, or none
    Table misses{{"case", "variant", "metric", "error", "cause"}, {}, {}};
    for (const auto& c : cases)
        for (const auto& r : c.runs) {
            if (!r.analysed) continue;
            for (const auto& x : r.analysis.metrics) {
                if (!x.judged() || x.pass()) continue;
                const MissCause cause = miss_cause(c.scene, r.variant, x, r.dt);
                misses.rows.push_back({c.name, r.variant.name, x.name,
                                       x.has_reference && x.measured && x.reference != 0.0 ? percent_text(x.relative_error()) : "",
                                       (cause.known ? "" : "unexplained: ") + cause.text});
                misses.links.push_back({c.name, "", "", "", ""});
            }
        }
    if (!misses.rows.empty()) {
        d.heading(3, "Misses and their causes");
        d.table(misses);
    }

    d.heading(2, "Conventions");
    d.bullets(conventions());

    for (const auto& c : cases) {
        d.heading(2, c.name);
        d.paragraph(c.scene.description + ". Reference: " + reference_text(c.scene) + ".");
        auto it = figures.images.find(c.name);
        if (it != figures.images.end())
            for (const auto& img : it->second)
                d.image(img, img.find("snapshots") != std::string::npos
                                 ? c.name + ": the cube on the incline every 0.25 s, per variant (x-z projection)"
                                 : c.name + ": every variant over the analytic curve (top: " + analytic_label(c) +
                                       "), difference (bottom)");
        if (const auto page = ctx.replays.find(c.name); page != ctx.replays.end())
            d.page(page->second, c.name + ": 3-D replay of every variant side by side (" + page->second + ")");
        else if (!ctx.replay_note.empty())
            d.paragraph(c.name + ": " + ctx.replay_note + ".");
        Table m{{"variant", "metric", "value", "reference", "rel. error", "tolerance", "verdict", "basis"}, {}};
        for (const auto& r : c.runs) {
            if (!r.analysed) {
                m.rows.push_back({r.variant.name, "run", "", "", "", "", run_verdict(r) + ": " + r.message, ""});
                continue;
            }
            for (const auto* list : {&r.analysis.metrics, &r.diffs})
                for (const auto& x : *list)
                    m.rows.push_back({r.variant.name, x.name, x.measured ? number_text(x.value) + (x.unit.empty() ? "" : " " + x.unit) : "not measured",
                                      x.has_reference ? number_text(x.reference) : "",
                                      x.has_reference && x.measured && x.reference != 0.0 ? percent_text(x.relative_error()) : "",
                                      x.tolerance_text(), x.verdict(), x.basis});
        }
        d.table(m);
        Table w{{"variant", "status", "dt (s)", "steps", "wall s", "outputs"}, {}};
        for (const auto& r : c.runs)
            w.rows.push_back({r.variant.name, validation::outcome_text(r.outcome), number_text(r.dt), std::to_string(r.steps),
                              fixed_text(r.wall_seconds, 3), r.outcome == Outcome::refused ? "" : r.out_dir});
        d.table(w);
    }

    d.heading(2, "Capability matrix");
    std::vector<Feature> features;
    std::set<Feature> seen;
    for (const auto& b : ctx.backends)
        for (const auto& f : b.capabilities)
            if (seen.insert(f.feature).second) features.push_back(f.feature);
    Table cap{{"feature"}, {}};
    for (const auto& b : ctx.backends) cap.header.push_back(b.name);
    for (const auto& f : features) {
        std::vector<std::string> row{to_string(f)};
        for (const auto& b : ctx.backends) {
            std::string cell = "-";
            for (const auto& x : b.capabilities)
                if (x.feature == f) cell = std::string(to_string(x.support)) + (x.how.empty() ? "" : ": " + x.how);
            row.push_back(cell);
        }
        cap.rows.push_back(row);
    }
    d.table(cap);
    return d;
}

}  // namespace cairn::report
