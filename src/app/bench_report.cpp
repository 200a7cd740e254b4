#include "app/bench_report.h"

#include <cmath>
#include <cstdio>

#include "app/plot_bench_script.h"
#include "core/error.h"
#include "core/file_util.h"
#include "core/log.h"
#include "core/process.h"

namespace hipr::app {
namespace fs = std::filesystem;

namespace {

// AUC horizons in work units: the headline (1) and the longer views of
// docs/method.md#measuring-run-time-against-error.
constexpr double kHorizons[] = {1.0, 4.0, 16.0};

// Debian's python3-matplotlib belongs to /usr/bin/python3; another python3 earlier in PATH
// (pyenv, a venv) usually lacks it.
std::string python_for_plots() {
  std::error_code ec;
  return std::filesystem::exists("/usr/bin/python3", ec) ? "/usr/bin/python3" : "python3";
}

std::string auc_key(const char* metric, double horizon) {
  return horizon == 1.0 ? std::string("auc_") + metric
                        : "auc_" + std::string(metric) + "_" + std::to_string(int(horizon));
}

nlohmann::json policy_summary(const bench::PolicyRun& run) {
  nlohmann::json j;
  for (double h : kHorizons) {
    j[auc_key("relmse", h)] = bench::error_auc(run.curve, bench::Metric::RelMse, h);
    j[auc_key("flip", h)] = bench::error_auc(run.curve, bench::Metric::Flip, h);
  }
  if (!run.curve.empty() && run.curve.front().focus_relmse >= 0.0)  // the focus region's own error
    for (double h : kHorizons) {
      j[auc_key("focus_relmse", h)] = bench::error_auc(run.curve, bench::Metric::FocusRelMse, h);
      j[auc_key("focus_flip", h)] = bench::error_auc(run.curve, bench::Metric::FocusFlip, h);
    }
  const auto or_null = [](double v) {
    return v < 0.0 ? nlohmann::json(nullptr) : nlohmann::json(v);
  };
  j["first_feedback_work"] = or_null(run.first_feedback_work);
  j["first_feedback_ms"] = or_null(run.first_feedback_ms);
  j["changed_tiles_shown_work"] = or_null(run.changed_tiles_shown_work);
  j["changed_tiles_shown_ms"] = or_null(run.changed_tiles_shown_ms);
  j["overhead_seconds"] = run.overhead_seconds;
  j["seconds"] = run.wall_seconds;
  j["overhead_share"] = run.wall_seconds > 0.0 ? run.overhead_seconds / run.wall_seconds : 0.0;
  j["converged"] = run.converged;
  j["stale_relmse"] = run.curve.front().relmse;
  j["stale_flip"] = run.curve.front().flip;
  j["final_relmse"] = run.curve.back().relmse;
  j["final_flip"] = run.curve.back().flip;
  j["final_work"] = run.curve.back().work;
  j["nonfinite_samples"] = run.non_finite_samples;
  if (run.drag_work >
      0.0) {  // a drag: the mean error while dragging and over the work unit after it
    j["drag_work"] = run.drag_work;
    for (const auto& [name, metric] :
         {std::pair{"relmse", bench::Metric::RelMse}, std::pair{"flip", bench::Metric::Flip}}) {
      j[std::string("auc_") + name + "_during_drag"] =
          bench::error_mean(run.curve, metric, 0.0, run.drag_work);
      j[std::string("auc_") + name + "_after_drag"] =
          bench::error_mean(run.curve, metric, run.drag_work, run.drag_work + 1.0);
    }
  }
  return j;
}

// Geometric mean over edits of a / b for one summary key; null when a policy is missing (with
// `only_where_run`: over the edits that ran both).
nlohmann::json ratio(const nlohmann::json& edits, const std::string& a, const std::string& b,
                     const std::string& key, bool only_where_run = false) {
  double log_sum = 0.0;
  int count = 0;
  for (const auto& edit : edits) {
    const auto& p = edit.at("policies");
    if (!p.contains(a) || !p.contains(b) || !p.at(a).contains(key) || !p.at(b).contains(key)) {
      if (only_where_run) continue;
      return nullptr;
    }
    const double x = p.at(a).at(key), y = p.at(b).at(key);
    if (!(x > 0.0) || !(y > 0.0)) continue;  // an exact image has no ratio to speak of
    log_sum += std::log(x / y);
    ++count;
  }
  return count ? nlohmann::json(std::exp(log_sum / count)) : nlohmann::json(nullptr);
}

}  // namespace

BenchEdit& BenchReport::add_edit(const std::string& name, ImageRGB reference, size_t changed_tiles,
                                 uint32_t tiles) {
  m_edits.push_back({name, std::move(reference), changed_tiles, tiles, {}});
  return m_edits.back();
}

nlohmann::json BenchReport::summary() const {
  nlohmann::json edits = nlohmann::json::array();
  for (const BenchEdit& edit : m_edits) {
    nlohmann::json policies = nlohmann::json::object();
    for (const auto& [name, run] : edit.runs) policies[name] = policy_summary(run);
    edits.push_back({{"name", edit.name},
                     {"changed_tiles", edit.changed_tiles},
                     {"reference_changed_tiles", edit.reference_changed_tiles},
                     {"active_and_changed_tiles", edit.active_and_changed_tiles},
                     {"tiles", edit.tiles},
                     {"policies", policies}});
  }
  nlohmann::json ratios = nlohmann::json::object();
  for (const char* metric : {"relmse", "flip"})
    for (const char* other : {"full", "oracle"}) {
      ratios[std::string("hipr_vs_") + other + "_auc_" + metric] =
          ratio(edits, "hipr", other, auc_key(metric, 1.0));
      for (double h : {4.0, 16.0})
        ratios[std::string("hipr_vs_") + other + "_" + auc_key(metric, h)] =
            ratio(edits, "hipr", other, auc_key(metric, h));
      for (const char* phase : {"_during_drag", "_after_drag"}) {
        const std::string key = std::string("auc_") + metric + phase;
        bool drag = !edits.empty();
        for (const auto& edit : edits)
          for (const auto& [policy, summary] : edit.at("policies").items())
            drag = drag && summary.contains(key);
        if (drag)
          ratios[std::string("hipr_vs_") + other + "_" + key] = ratio(edits, "hipr", other, key);
      }
    }
  // Attention-guided rendering: the focus region's error with the focus against without.
  bool focused = false;
  for (const auto& edit : edits) focused = focused || edit.at("policies").contains(kFocusedHipr);
  for (const char* metric : {"focus_relmse", "focus_flip"})
    for (double h : kHorizons)
      if (focused) {
        const std::string key = auc_key(metric, h);
        ratios[std::string(kFocusedHipr) + "_vs_hipr_" + key] =
            ratio(edits, kFocusedHipr, "hipr", key, true);
      }
  return {{"scene", m_scene}, {"settings", m_settings}, {"edits", edits}, {"ratios", ratios}};
}

void BenchReport::write_curves(const fs::path& path) const {
  std::string csv = "edit,policy,step,work,wall_ms,relmse,flip,focus_relmse,focus_flip\n";
  char line[256];
  for (size_t e = 0; e < m_edits.size(); ++e)
    for (const auto& [name, run] : m_edits[e].runs)
      for (const bench::CurvePoint& p : run.curve) {
        std::snprintf(line, sizeof line, "%zu,%s,%u,%.6f,%.3f,%.8g,%.8g,%.8g,%.8g\n", e + 1,
                      name.c_str(), p.step, p.work, p.wall_ms, p.relmse, p.flip, p.focus_relmse,
                      p.focus_flip);
        csv += line;
      }
  write_text_atomically(path, csv);
}

void BenchReport::write_images() const {
  // Tone-mapped to look at, linear to measure (`hipr compare`).
  for (const char* format : {".png", ".exr"})
    for (size_t e = 0; e < m_edits.size(); ++e) {
      const std::string stem = "edit" + std::to_string(e + 1);
      const DisplayTransform display = display_transform(m_display, m_edits[e].reference);
      write_image(m_folder / (stem + "_reference" + format), m_edits[e].reference, {}, display);
      for (const auto& [name, run] : m_edits[e].runs)
        for (const auto& [work, image] : run.captures) {
          char label[32];
          std::snprintf(label, sizeof label, "_work%g%s", work, format);
          write_image(m_folder / (stem + "_" + name + label), image, {}, display);
        }
    }
}

void BenchReport::write() const {
  write_curves(m_folder / "curves.csv");
  write_text_atomically(m_folder / "summary.json", summary().dump(2) + "\n");
  write_images();
  const fs::path plot = m_folder / "plot.png";
  write_atomically(plot, [&](const fs::path& temp) {
    const ProcessResult result =
        run_process({python_for_plots(), "-", (m_folder / "curves.csv").string(),
                     (m_folder / "summary.json").string(), temp.string()},
                    plot_bench_script());
    if (result.exit_code != 0) {
      std::string why =
          result.output.empty() ? "exit code " + std::to_string(result.exit_code) : result.output;
      if (const size_t end = why.find_last_not_of("\n"); end != std::string::npos)
        why.resize(end + 1);
      if (const size_t last = why.rfind('\n'); last != std::string::npos)
        why = why.substr(last + 1);
      throw InternalError("plotting failed (tools/plot_bench.py needs python3-matplotlib): " + why);
    }
  });
}

}  // namespace hipr::app
