// `hipr compare A B [--metric flip|relmse|rmse|max] [--threshold T] [--percentile P] [--heatmap
// FILE.png]
// [--json FILE]`: for screenshot-regression suites. Exit 0 when the images agree within the
// threshold, 1 when they differ (or either holds a NaN or infinity), 2 on bad input. PNG/JPEG
// values are sRGB-encoded: they are decoded to linear first, so every format compares as
// radiance (FLIP then tone-maps as the project's PNG output does).
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <optional>

#include "app/commands.h"
#include "app/display_flags.h"
#include "core/error.h"
#include "core/file_util.h"
#include "image/debug_images.h"
#include "image/image_compare.h"
#include "image/image_io.h"

namespace hipr::app {
namespace {
namespace fs = std::filesystem;

struct CompareOptions {
  fs::path a, b;
  std::string metric = "flip";
  double threshold = 0.0;
  std::optional<double> percentile;
  fs::path heatmap;
  fs::path json;
  DisplayFlags display;  // FLIP's tone mapping
  bool quiet = false;
};

bool srgb_encoded(const fs::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".png" || ext == ".jpg" || ext == ".jpeg";
}

ImageRGB read_linear(const fs::path& path) {
  if (!fs::is_regular_file(path)) throw InputError("no such image: " + path.string());
  ImageRGB image = read_image(path);
  if (srgb_encoded(path))
    for (float& v : image.rgb)
      v = v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
  return image;
}

std::string format_percentile(double p) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", p);
  return text;
}

int run_compare(const CompareOptions& o) {
  const CompareMetric metric = parse_compare_metric(o.metric);
  if (!std::isfinite(o.threshold) || o.threshold < 0.0)
    throw InputError("--threshold must be a finite number >= 0");
  if (o.percentile && !(*o.percentile > 0.0 && *o.percentile <= 100.0))
    throw InputError("--percentile must be in (0, 100]");
  if (!o.heatmap.empty() && o.heatmap.extension() != ".png")
    throw InputError("--heatmap writes a .png");
  const ImageRGB a = read_linear(o.a), b = read_linear(o.b);
  // An automatic exposure is metered on the reference, so both images see the same one.
  const DisplayTransform display = display_transform(o.display, b);
  FlipOptions flip;
  flip.exposure_ev = display.exposure_ev;
  flip.tone_mapper = display.tone_mapper;
  const ImageComparison c = compare_images(a, b, metric, o.threshold, o.percentile, flip);
  const std::string measure =
      o.percentile ? o.metric + " p" + format_percentile(*o.percentile) : o.metric;
  const bool same = c.within(o.threshold);
  const double share =
      a.width && a.height ? double(c.pixels_over) / (double(a.width) * a.height) : 0.0;

  if (!o.heatmap.empty()) {
    float scale = metric == CompareMetric::Flip ? 1.0f : float(o.threshold);
    for (float e : c.pixel_error)
      if (std::isfinite(e)) scale = std::max(scale, e);
    write_image(o.heatmap,
                error_heat_image(c.pixel_error, scale > 0.0f ? scale : 1.0f, a.width, a.height));
  }
  nlohmann::json box = nullptr;
  if (c.box) box = {c.box->x0, c.box->y0, c.box->x1, c.box->y1};
  if (!o.json.empty()) {
    const nlohmann::json report = {
        {"a", o.a.string()},
        {"b", o.b.string()},
        {"metric", o.metric},
        {"percentile", o.percentile ? nlohmann::json(*o.percentile) : nlohmann::json(nullptr)},
        {"value", std::isfinite(c.value) ? nlohmann::json(c.value) : nlohmann::json(nullptr)},
        {"threshold", o.threshold},
        {"same", same},
        {"width", a.width},
        {"height", a.height},
        {"pixels_over", c.pixels_over},
        {"share_over", share},
        {"nonfinite_pixels", c.nonfinite_pixels},
        {"box", box}};
    write_text_atomically(o.json, report.dump(2) + "\n");
  }
  if (!o.quiet) {
    std::printf("%s %s %s %.6g (threshold %g): %s", o.a.filename().string().c_str(),
                o.b.filename().string().c_str(), measure.c_str(), c.value, o.threshold,
                same ? "same" : "different");
    if (c.box)
      std::printf(", %llu pixels over (%.3g %%) in x %u..%u, y %u..%u",
                  (unsigned long long)c.pixels_over, 100.0 * share, c.box->x0, c.box->x1, c.box->y0,
                  c.box->y1);
    if (c.nonfinite_pixels)
      std::printf(", %llu non-finite pixels", (unsigned long long)c.nonfinite_pixels);
    std::printf("\n");
  }
  return same ? kExitOk : kExitDifferent;
}

}  // namespace

Command add_compare_command(CLI::App& app) {
  auto options = std::make_shared<CompareOptions>();
  CLI::App* cmd = app.add_subcommand("compare",
                                     "Compare two images (EXR, PNG, HDR): exit 0 within the "
                                     "threshold, 1 when different, 2 on bad input");
  cmd->add_option("a", options->a, "Image (the one under test)")->required();
  cmd->add_option("b", options->b, "Image (the reference; relmse divides by it)")->required();
  cmd->add_option("--metric", options->metric, "flip, relmse, rmse or max")->capture_default_str();
  cmd->add_option("--threshold", options->threshold,
                  "Largest value that still counts as the same (also the "
                  "per-pixel error above which a pixel counts as different)")
      ->capture_default_str();
  cmd->add_option("--percentile", options->percentile,
                  "Judge the P-th percentile of the per-pixel errors (e.g. 99.9: the worst pixels) "
                  "instead of the "
                  "metric over the image");
  cmd->add_option("--heatmap", options->heatmap, "Write the per-pixel error as a heat map (.png)");
  cmd->add_option("--json", options->json, "Write the comparison as JSON");
  add_display_flags(*cmd, options->display, "FLIP (it compares what a screen shows)");
  cmd->add_flag("-q,--quiet", options->quiet, "Print nothing but errors");
  return {cmd, [options] { return run_compare(*options); }};
}

}  // namespace hipr::app
