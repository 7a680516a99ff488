#include "scene_compare/compare_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>
#include <sstream>

#include "cases/case_util.hpp"
#include "cases/scene_stack.hpp"
#include "output/atomic_write.hpp"
#include "report/case_replay.hpp"
#include "report/figures.hpp"
#include "report/palette.hpp"
#include "report/text.hpp"
#include "scene_compare/block_diff.hpp"
#include "scene_compare/compare_figures.hpp"

namespace fs = std::filesystem;

namespace cairn::scene_compare {

using report::number_text;
using validation::CaseResult;
using validation::CaseRun;

Baseline choose_baseline(const CaseResult& result, const std::string& wanted) {
    auto completed = [](const CaseRun& r) { return r.outcome == Outcome::completed && r.samples.size() >= 2; };
    for (const auto& r : result.runs)
        if (!wanted.empty() && r.variant.name == wanted && completed(r)) return {&r, "chosen with --baseline"};
    for (const auto& r : result.runs)
        if (r.variant.name == "dem-rigid" && completed(r))
            return {&r, wanted.empty() ? "the default" : "the default (" + wanted + " did not complete)"};
    for (const auto& r : result.runs)
        if (completed(r)) return {&r, "the first variant that completed (dem-rigid did not run or complete)"};
    return {};
}

namespace {

std::string or_never(double t) { return std::isnan(t) ? "never" : number_text(t, 4); }

std::string run_note(const CaseRun& r) {
    std::string m = r.message;
    if (!r.energy_created.empty()) m += (m.empty() ? "" : "; ") + r.energy_created;
    if (m.size() > 200) m = m.substr(0, 197) + "...";
    return m.empty() ? "-" : m;
}

/// the energies of a run's last sample, the largest balance error on the way and the largest gain
std::vector<std::string> energy_row(const CaseRun& r) {
    const Energies& e = r.samples.back().energy;
    const double e0 = r.samples.front().energy.total();
    double worst = 0.0;
    for (const auto& s : r.samples) worst = std::max(worst, std::abs(s.energy.total() - e0));
    return {r.variant.name,         number_text(e.kinetic, 4),   number_text(e.potential - r.samples.front().energy.potential, 4),
            number_text(e.contact, 4), number_text(e.strain, 4), number_text(e.dissipated, 4),
            number_text(e.external, 4), number_text(e.total() - e0, 3), number_text(worst, 3), number_text(r.energy_gain, 3)};
}

std::vector<std::string> contact_row(const CaseRun& r) {
    int most = 0;
    double sum = 0.0;
    for (const auto& s : r.samples) {
        most = std::max(most, s.contacts);
        sum += s.contacts;
    }
    return {r.variant.name, std::to_string(r.samples.front().contacts), std::to_string(r.samples.back().contacts),
            std::to_string(most), number_text(sum / double(r.samples.size()), 4)};
}

/// the bullet on dem's compliant joints against the engines' rigid contact, when the comparison
/// has both, naming the dem variants whose largest rotation is far from the rigid engines'
/// (`peaks_of[v][b]`: variant v's peaks of free block b)
std::string compliance_text(const std::vector<VariantHistories>& variants,
                            const std::vector<std::vector<BlockPeaks>>& peaks_of, const Scene& scene) {
    std::vector<VariantPeak> peaks;
    bool compliant = false, rigid = false;
    for (size_t v = 0; v < variants.size(); ++v) {
        const auto& variant = variants[v].run->variant;
        VariantPeak p{variant.name, variant.backend == "dem", !variant.penalty(), 0.0};
        for (const BlockPeaks& b : peaks_of[v]) p.angle = std::max(p.angle, b.angle);
        compliant = compliant || p.compliant;
        rigid = rigid || p.rigid;
        peaks.push_back(p);
    }
    if (!compliant || !rigid) return {};
    std::string text = "Compliant against rigid joints: dem puts springs of kn = " + number_text(scene.contact.kn, 3) +
                       " N/m³ (ks = " + number_text(scene.contact.ks, 3) +
                       " N/m³) over every joint, the rigid modes none. Near a threshold (a block or column just above "
                       "the ground acceleration that uplifts it, an arch near its least thickness) that compliance "
                       "alone can change the outcome (docs/dem.md, \"Rocking under a pulse\" and \"An arch near its "
                       "minimum thickness needs stiff joints\"); dem approaches the rigid answer as kn grows, so rerun "
                       "it stiffer (--set contact.kn=... --set contact.ks=...) to tell the joints' compliance from an "
                       "engine's error.";
    // a stack pushed by the ground: how much the joints' springs alone lower its overturning
    // multiplier (the quasi-static peak of BlockStack's Winkler joints against B/H)
    if (const auto stack = cases::centred_stack(scene)) {
        const double rigid_lambda = stack->rigid_multiplier(), soft = stack->winkler_multiplier(scene.contact.kn);
        if (rigid_lambda < scene.contact.friction && soft > 0.0)
            text += " For this stack of " + std::to_string(stack->layers.size()) +
                    (stack->layers.size() == 1 ? " layer" : " layers") +
                    " under the ground motion, joints of kn = " + number_text(scene.contact.kn, 3) +
                    " N/m³ alone lower the quasi-static overturning multiplier a/g from " + fixed_text(rigid_lambda, 4) +
                    " (rigid) to " + fixed_text(soft, 4) + " (" + fixed_text(100.0 * (soft / rigid_lambda - 1.0), 1) +
                    " %, BlockStack::winkler_multiplier; docs/validation.md, \"Penalty joints lean\").";
    }
    const std::string far = compliance_disagreement(peaks);
    if (!far.empty())
        text += " Here the largest rotations differ: " + far +
                "; the cause may be the compliance or a row of \"What each engine could not represent\" below "
                "(friction against twisting, for one).";
    return text;
}

/// the bullet on deformable blocks soft against their joints, when a dem variant runs them: the
/// largest kn·h/E among the free blocks (docs/validation.md, "A flexible block rocking")
std::string flexibility_text(const std::vector<VariantHistories>& variants, const Scene& scene) {
    const bool deformable = std::any_of(variants.begin(), variants.end(), [](const VariantHistories& v) {
        return v.run->variant.backend == "dem" && v.run->variant.model == "deformable";
    });
    if (!deformable) return {};
    double most = 0.0;
    std::string name;
    for (size_t b = 0; b < scene.blocks.size(); ++b) {
        if (scene.blocks[b].fixed) continue;
        const double r = cases::joint_to_block_stiffness(scene, int(b));
        if (r > most) most = r, name = scene.blocks[b].name;
    }
    if (most <= cases::kRigidAgainstJoints) return {};
    return "Deformable against rigid blocks: block " + name + " is soft against its joints (kn·h/E = " +
           number_text(most, 3) + ", above " + number_text(cases::kRigidAgainstJoints, 3) +
           "): at each impact the deformable block vibrates and trades energy with its rocking, so after its first "
           "impact dem-deformable may leave dem-rigid, as a flexible body does (docs/validation.md, \"A flexible "
           "block rocking\"). The references of a block rocking freely (housner, winkler_rocking) judge it up "
           "to its first impact only.";
}

/// false for a capability row the scene does not use (a damping it does not set, hexahedra it does
/// not have, deformable blocks the reference engines are never asked for, a structure held at rest
/// where one block moves alone); rows not named here apply
bool applies(Feature feature, const Scene& scene, bool engine) {
    if (feature == Feature::mass_damping) return scene.damping.alpha != 0.0;
    if (feature == Feature::stiffness_damping) return scene.damping.beta != 0.0;
    if (feature == Feature::normal_damping) return scene.contact.damping_rule != ContactDampingRule::none;
    if (feature == Feature::twist_friction) return scene.contact.friction > 0.0;
    if (feature == Feature::deformable_blocks) return !engine;
    // a structure: blocks that rest on each other, not one block on fixed ones
    if (feature == Feature::held_at_rest)
        return std::count_if(scene.blocks.begin(), scene.blocks.end(), [](const BlockDef& b) { return !b.fixed; }) > 1;
    if (feature == Feature::general_hexahedra)
        return std::any_of(scene.blocks.begin(), scene.blocks.end(), [](const BlockDef& b) { return b.shape == Shape::hexahedron; });
    return true;
}

std::string table_csv(const report::Table& t) {
    std::string o;
    auto line = [&](const std::vector<std::string>& cells) {
        for (size_t i = 0; i < cells.size(); ++i) o += (i ? "," : "") + report::csv_field(cells[i]);
        o += "\n";
    };
    line(t.header);
    for (const auto& r : t.rows) line(r);
    return o;
}

}  // namespace

report::Document write_compare_report(const CaseResult& result, const CompareContext& ctx, const std::string& dir,
                                      std::string& figure_note) {
    const Scene& scene = result.scene;
    report::Document d;
    d.title = "Comparison of " + result.name + " across engines";
    d.contents();

    const auto blocks = free_blocks(scene);
    std::vector<std::string> block_names;
    for (const auto& b : blocks) block_names.push_back(b.name);
    std::vector<VariantHistories> variants;
    for (const auto& r : result.runs) {
        if (r.samples.size() < 2) continue;
        VariantHistories v;
        v.run = &r;
        for (size_t b = 0; b < blocks.size(); ++b) v.blocks.push_back(block_history(r.samples, int(b)));
        variants.push_back(std::move(v));
    }
    const Baseline base = choose_baseline(result, ctx.baseline);
    int base_index = -1;
    for (size_t v = 0; v < variants.size(); ++v)
        if (variants[v].run == base.run) base_index = int(v);

    // summary
    d.heading(2, "Summary");
    char line[400];
    std::snprintf(line, sizeof line,
                  "%zu free block%s, %zu fixed, %g s simulated. %zu variants listed, %zu produced results. "
                  "Wall time %.1f s with %d run%s at a time.",
                  blocks.size(), blocks.size() == 1 ? "" : "s", scene.blocks.size() - blocks.size(), scene.run.duration,
                  result.runs.size(), variants.size(), ctx.wall_seconds, ctx.jobs, ctx.jobs == 1 ? "" : "s");
    d.paragraph((scene.description.empty() ? "" : scene.description + ". ") + line);
    d.paragraph("Scene: " + ctx.scene_label + ". Command: " + ctx.command);
    report::Table runs{{"variant", "colour in figures", "engine", "contact", "block model", "outcome", "steps (count)", "time step (s)",
                        "wall time (s)", "note"},
                       {}};
    for (const auto& r : result.runs)
        runs.rows.push_back({r.variant.name, report::variant_colour_name(r.variant.name), r.variant.backend, r.variant.contact_label(), r.variant.model,
                             validation::outcome_text(r.outcome), r.steps ? std::to_string(r.steps) : "-",
                             r.dt > 0 ? number_text(r.dt, 3) : "-", number_text(r.wall_seconds, 3), run_note(r)});
    d.table(runs);
    // what the engines warned about their own runs (run.json's notes that begin "warning: ")
    std::vector<std::string> warned;
    for (const auto& r : result.runs)
        for (const auto& w : r.warnings) warned.push_back(r.variant.name + ": " + w.substr(9));
    if (!warned.empty()) {
        d.paragraph("Warnings the engines gave about their runs:");
        d.bullets(warned);
    }

    std::vector<std::vector<BlockPeaks>> peaks_of(variants.size());   // [variant][free block]
    for (size_t v = 0; v < variants.size(); ++v)
        for (const auto& h : variants[v].blocks) peaks_of[v].push_back(block_peaks(h));
    // the blocks with figures and rows in the document: those that moved most when not all fit
    const std::vector<size_t> shown = blocks_to_show(peaks_of, blocks.size(), ctx.max_block_figures);
    const bool all_shown = shown.size() == blocks.size();
    auto is_shown = [&](size_t b) { return std::binary_search(shown.begin(), shown.end(), b); };
    write_data(variants, base_index, shown, dir);
    const auto images = draw_figures(variants, base_index, block_names, shown, dir, figure_note);
    auto has = [&](const std::string& p) { return std::find(images.begin(), images.end(), p) != images.end(); };

    // verdicts against the analytic reference
    if (scene.reference) {
        d.heading(2, "Verdicts against the analytic reference");
        d.paragraph("The scene declares an analytic reference (" + scene.reference->kind +
                    "); every variant is judged as cairn validate judges the shipped cases (docs/validation.md).");
        report::Table v{{"variant", "verdict", "worst metric"}, {}};
        for (const auto& r : result.runs) v.rows.push_back({r.variant.name, report::run_verdict(r), report::worst_metric_text(r)});
        d.table(v);
        report::Table m{{"variant", "metric", "value", "reference", "tolerance", "verdict", "basis"}, {}};
        for (const auto& r : result.runs)
            if (r.analysed)
                for (const auto& x : r.analysis.metrics) {
                    const std::string unit = x.unit.empty() ? "" : " " + x.unit;
                    m.rows.push_back({r.variant.name, x.name, number_text(x.value) + unit,
                                      x.has_reference ? number_text(x.reference) + unit : "-", x.tolerance_text(),
                                      x.verdict(), x.basis});
                }
        d.table(m);
        const auto fig = report::write_figures({result}, dir);
        if (!fig.note.empty()) figure_note += fig.note;
        const auto it = fig.images.find(result.name);
        if (it != fig.images.end())
            for (const auto& img : it->second)
                d.image(img, "Every variant over the analytic curve (black), with its difference below.");
    }

    // differences
    d.heading(2, "How the variants are compared");
    DivergenceThresholds th;
    std::vector<std::string> how{
        "Baseline: " + (base.run ? base.run->variant.name + " (" + base.why + ")" : std::string("none (no variant completed)")) + ".",
        "Position: the centre of mass of each free block. Rotation angle: the angle of the rotation from the "
        "block's orientation at t = 0 (0 to π rad, about whatever axis). Speed: the magnitude of the "
        "centre-of-mass velocity.",
        "Differences are taken at each variant's output times, the baseline interpolated linearly, over the "
        "time both runs cover. RMS = root mean square over those times.",
        "First divergence: the first time the distance between the centres of mass exceeds 1 % of the block's "
        "smallest edge, or the rotation angles differ by more than " + number_text(th.angle) + " rad; \"never\" when "
        "they stay within that.",
        "Each variant keeps one colour in every figure.",
    };
    const std::string compliance = compliance_text(variants, peaks_of, scene);
    if (!compliance.empty()) how.push_back(compliance);
    const std::string flexibility = flexibility_text(variants, scene);
    if (!flexibility.empty()) how.push_back(flexibility);
    d.bullets(how);

    report::Table diff{{"block", "variant", "position RMS (m)", "position diverged at (s)", "largest distance (m)",
                        "rotation RMS (rad)", "rotation diverged at (s)", "largest rotation difference (rad)",
                        "speed RMS (m/s)", "compared until (s)"},
                       {}};
    report::Table peaks{{"block", "variant", "largest displacement (m)", "largest rotation (rad)", "largest speed (m/s)"}, {}};
    report::Table diff_shown{diff.header, {}}, peaks_shown{peaks.header, {}};   // the document's rows
    for (size_t b = 0; b < blocks.size(); ++b) {
        th.position = 0.01 * blocks[b].size;
        for (size_t v = 0; v < variants.size(); ++v) {
            const BlockPeaks& p = peaks_of[v][b];
            peaks.rows.push_back({blocks[b].name, variants[v].run->variant.name, number_text(p.displacement, 4),
                                  number_text(p.angle, 4), number_text(p.speed, 4)});
            if (is_shown(b)) peaks_shown.rows.push_back(peaks.rows.back());
            if (base_index < 0 || int(v) == base_index) continue;
            const auto x = block_diff(variants[v].blocks[b], variants[size_t(base_index)].blocks[b], th);
            diff.rows.push_back({blocks[b].name, variants[v].run->variant.name, number_text(x.position_rms, 4),
                                 or_never(x.position_diverged), number_text(x.position_peak, 4),
                                 number_text(x.angle_rms, 4), or_never(x.angle_diverged), number_text(x.angle_peak, 4),
                                 number_text(x.speed_rms, 4), number_text(x.compared_until, 4)});
            if (is_shown(b)) diff_shown.rows.push_back(diff.rows.back());
        }
    }
    write_text_atomic((fs::path(dir) / "differences.csv").string(), table_csv(diff));
    write_text_atomic((fs::path(dir) / "peaks.csv").string(), table_csv(peaks));
    // the document shows the blocks that have figures; the CSVs hold every block
    const std::string which = std::to_string(shown.size()) + " of the " + std::to_string(blocks.size()) +
                              " free blocks that moved most (largest displacement over every variant, then rotation)";
    const std::string more = all_shown ? std::string() : " Shown: the " + which + ".";
    if (base.run) {
        d.heading(2, "Differences from " + base.run->variant.name);
        d.paragraph("Per free block and variant (every block in differences.csv)." + more);
        d.table(diff_shown);
    }
    d.heading(2, "Peak values");
    d.paragraph("Per free block and variant: the largest distance from the position at t = 0, rotation angle and "
                "speed (every block in peaks.csv)." + more);
    d.table(peaks_shown);

    // per block figures
    d.heading(2, "Blocks");
    std::string replay_note;
    if (report::write_case_replay(result, dir, "replay.html", replay_note).empty()) d.paragraph(replay_note + ".");
    else d.page("replay.html", "3-D replay of every variant side by side (replay.html)");
    if (!images.empty() && !all_shown)
        d.paragraph("Figures, and histories in data/, for the " + which + "; every block is in the runs' "
                    "trajectory.csv.");
    if (images.empty()) d.paragraph("No figures: " + (figure_note.empty() ? std::string("nothing to draw") : figure_note));
    for (size_t b : shown) {
        const std::string stem = "figures/block" + std::to_string(b + 1);
        if (!has(stem + ".png")) continue;
        d.heading(3, blocks[b].name);
        d.image(stem + ".png", blocks[b].name + ": position, rotation angle and speed of every variant");
        if (has(stem + "_diff.png"))
            d.image(stem + "_diff.png", blocks[b].name + ": difference of every variant to " + base.run->variant.name);
    }

    // energies and contacts
    d.heading(2, "Energy");
    d.paragraph("At the end of each run, in J. Potential energy is counted from its value at t = 0; work by loads "
                "is the work of ground motion and other loads; balance error = total energy (kinetic + potential + "
                "contact + strain + dissipated − work) minus its value at t = 0; the largest balance error is its largest "
                "magnitude during the run; the largest gain is its largest rise above its lowest earlier value: energy "
                "that appeared without a source (losses a backend does not book, such as the rigid engines' impacts, "
                "lower the balance error and are no gain). A gain beyond 10 % of the motion's energy (at least of the heaviest block's m·g·diameter) is named in the "
                "variant's note above. Histories in data/<variant>_energy.csv.");
    report::Table en{{"variant", "kinetic (J)", "potential change (J)", "contact (J)", "strain (J)", "dissipated (J)",
                      "work by loads (J)", "balance error (J)", "largest balance error (J)", "largest gain (J)"},
                     {}};
    report::Table co{{"variant", "at t = 0 (count)", "at the end (count)", "largest (count)", "mean (count)"}, {}};
    for (const auto& v : variants) {
        en.rows.push_back(energy_row(*v.run));
        co.rows.push_back(contact_row(*v.run));
    }
    d.table(en);
    write_text_atomic((fs::path(dir) / "energy.csv").string(), table_csv(en));
    if (has("figures/energy.png"))
        d.image("figures/energy.png", "Kinetic energy, balance error and contact points of every variant");
    d.heading(2, "Contacts");
    d.paragraph("Active contact points: for dem and the matched engines the penalty hitting points in contact, for "
                "the engines' own rigid contact the engine's contact points; counts are not comparable across "
                "those two kinds.");
    d.table(co);

    // what each engine could not represent
    d.heading(2, "What each engine could not represent");
    d.paragraph("The rows of the capability matrix (cairn list) that this scene uses and an engine does not "
                "represent exactly, and the variants an engine refused.");
    report::Table cap{{"engine", "feature", "support", "what is done instead"}, {}};
    std::set<std::string> used;
    for (const auto& r : result.runs) used.insert(r.variant.backend);
    for (const auto& b : ctx.backends) {
        if (!used.count(b.name)) continue;
        for (const auto& f : b.capabilities)
            if (f.support != Support::exact && applies(f.feature, scene, b.name != "dem")) cap.rows.push_back({b.name, to_string(f.feature), to_string(f.support), f.how.empty() ? "-" : f.how});
    }
    for (const auto& r : result.runs)
        if (r.outcome == Outcome::refused)
            cap.rows.push_back({r.variant.name, "this scene", "refused", run_note(r)});
    if (cap.rows.empty()) d.paragraph("Every engine represents every feature exactly.");
    else d.table(cap);

    d.heading(2, "Files");
    d.bullets({"differences.csv, peaks.csv, energy.csv: the tables above.",
               "data/<variant>_block<k>.csv: t (s), x, y, z (m), rotation angle (rad), speed (m/s) of free block k "
               "(k counts the free blocks in the order of peaks.csv" + (all_shown ? std::string("") : "; the blocks shown only") + ").",
               "data/<variant>_block<k>_difference.csv: the same block's difference to the baseline.",
               "data/<variant>_energy.csv: the energy ledger (J) and contact count over time.",
               "runs/<scene>/<variant>/: each run's trajectory.csv and run.json, as cairn run writes them."});
    return d;
}

}  // namespace cairn::scene_compare
