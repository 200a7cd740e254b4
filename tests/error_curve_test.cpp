// The benchmark's summaries of an error curve: the displayed image is a step function of work.
#include "bench/error_curve.h"
#include "bench/reference_cache.h"

#include <gtest/gtest.h>

#include "core/error.h"

namespace hipr::bench {
namespace {

CurvePoint point(double work, double relmse, double flip = 0.0) {
  return {0, work, 0.0, relmse, flip};
}

TEST(ErrorAuc, IsTheMeanOfAStepFunctionOverTheHorizon) {
  // 0.4 on [0, 0.25), 0.2 on [0.25, 0.75), 0.1 from 0.75 on.
  const ErrorCurve curve = {point(0.0, 0.4, 1.0), point(0.25, 0.2, 0.5), point(0.75, 0.1, 0.25)};
  EXPECT_DOUBLE_EQ(error_auc(curve, Metric::RelMse, 1.0), 0.4 * 0.25 + 0.2 * 0.5 + 0.1 * 0.25);
  EXPECT_DOUBLE_EQ(error_auc(curve, Metric::Flip, 1.0), 1.0 * 0.25 + 0.5 * 0.5 + 0.25 * 0.25);
  EXPECT_DOUBLE_EQ(error_auc(curve, Metric::RelMse, 0.5), (0.4 * 0.25 + 0.2 * 0.25) / 0.5);
  // Past the last point its error holds.
  EXPECT_DOUBLE_EQ(error_auc(curve, Metric::RelMse, 4.0),
                   (0.4 * 0.25 + 0.2 * 0.5 + 0.1 * 3.25) / 4.0);
}

TEST(ErrorAuc, AStaleImageUntilTheHorizonScoresItsOwnError) {
  // `full` shows the stale image until its pass ends at exactly one work unit.
  const ErrorCurve curve = {point(0.0, 0.3), point(0.5, 0.3), point(1.0, 5.0)};
  EXPECT_DOUBLE_EQ(error_auc(curve, Metric::RelMse, 1.0), 0.3);
}

// A drag's summaries: the mean over a window of work (during the drag, the unit after it).
TEST(ErrorMean, IsTheMeanOfTheStepFunctionOverAWindow) {
  const ErrorCurve curve = {point(0.0, 0.4), point(0.25, 0.2), point(0.75, 0.1)};
  EXPECT_DOUBLE_EQ(error_mean(curve, Metric::RelMse, 0.0, 1.0),
                   error_auc(curve, Metric::RelMse, 1.0));
  EXPECT_DOUBLE_EQ(error_mean(curve, Metric::RelMse, 0.5, 1.0), (0.2 * 0.25 + 0.1 * 0.25) / 0.5);
  EXPECT_DOUBLE_EQ(error_mean(curve, Metric::RelMse, 1.0, 2.0), 0.1);
  EXPECT_THROW(error_mean(curve, Metric::RelMse, 0.5, 0.5), InternalError);
}

TEST(ErrorAuc, RefusesCurvesThatDoNotStartAtTheEditOrGoBack) {
  EXPECT_THROW(error_auc({}, Metric::RelMse, 1.0), InternalError);
  EXPECT_THROW(error_auc({point(0.1, 1.0)}, Metric::RelMse, 1.0), InternalError);
  EXPECT_THROW(error_auc({point(0.0, 1.0), point(0.5, 1.0), point(0.25, 1.0)}, Metric::RelMse, 1.0),
               InternalError);
  EXPECT_THROW(error_auc({point(0.0, 1.0)}, Metric::RelMse, 0.0), InternalError);
}

// A tile changed where the references before and after differ by more than noise: 12 % in one
// 8x8 tile of a 20x12 image (partial tiles at the edges), 2 % everywhere else.
TEST(ReferenceChangedTiles, FindsTheTilesThatDifferBeyondNoise) {
  ImageRGB before{20, 12, std::vector<float>(20 * 12 * 3, 1.0f)};
  ImageRGB after = before;
  for (float& v : after.rgb) v = 1.02f;
  for (uint32_t y = 8; y < 12; ++y)  // tile 4: x 8-15 of the bottom row, 4 rows high
    for (uint32_t x = 8; x < 16; ++x)
      for (int c = 0; c < 3; ++c) after.rgb[(size_t(y) * 20 + x) * 3 + size_t(c)] = 1.12f;
  EXPECT_EQ(reference_changed_tiles(before, after, 8), std::vector<uint32_t>{4});
  EXPECT_TRUE(reference_changed_tiles(before, before, 8).empty());
}

}  // namespace
}  // namespace hipr::bench
