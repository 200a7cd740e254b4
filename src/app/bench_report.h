#pragma once
// The outputs of `hipr bench`: curves.csv, summary.json, plot.png and per-edit images.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/display_flags.h"
#include "bench/policy_run.h"
#include "image/image_io.h"

namespace hipr::app {

// The name of the run of the hipr policy that follows the focus (the plain "hipr" run has none).
inline constexpr const char* kFocusedHipr = "hipr+focus";

struct BenchEdit {
  std::string name;
  ImageRGB reference;
  size_t changed_tiles = 0;  // stage 1's active set
  uint32_t tiles = 0;
  // Tiles the edit really changed (bench::reference_changed_tiles), and how many of them stage 1
  // made active.
  size_t reference_changed_tiles = 0, active_and_changed_tiles = 0;
  std::vector<std::pair<std::string, bench::PolicyRun>> runs;  // in the order run

  void add_run(const std::string& policy, bench::PolicyRun run) {
    runs.emplace_back(policy, std::move(run));
  }
};

class BenchReport {
 public:
  // `settings`: what the runs were made with, recorded in summary.json.
  // `display`: the PNGs' exposure and tone mapper (auto: metered on each edit's reference).
  BenchReport(std::string scene, nlohmann::json settings, std::filesystem::path folder,
              DisplayFlags display = {})
      : m_scene(std::move(scene)),
        m_settings(std::move(settings)),
        m_folder(std::move(folder)),
        m_display(display) {}
  BenchEdit& add_edit(const std::string& name, ImageRGB reference, size_t changed_tiles,
                      uint32_t tiles);
  // Writes everything (each file atomically); plot.png last, since it needs python3-matplotlib
  // (a missing one is an InternalError after the other outputs are written).
  void write() const;

 private:
  nlohmann::json summary() const;
  void write_curves(const std::filesystem::path& path) const;
  void write_images() const;

  std::string m_scene;
  nlohmann::json m_settings;
  std::filesystem::path m_folder;
  DisplayFlags m_display;
  std::vector<BenchEdit> m_edits;
};

}  // namespace hipr::app
