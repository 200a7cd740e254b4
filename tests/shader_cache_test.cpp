// The run-time shader compiler: every kernel compiles, and the on-disk cache is keyed by the
// defines, reused when nothing changed and ignored when corrupt.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <set>

#include "test_support.h"
#include "vk/compute_pipeline.h"
#include "vk/shader_compiler.h"

namespace hipr {
namespace {

class ShaderCache : public ::testing::Test {
 protected:
  void SetUp() override {
    m_dir = test::temp_dir("shader-cache");
    const char* old = std::getenv("HIPR_CACHE_DIR");
    m_previous = old ? old : "";
    setenv("HIPR_CACHE_DIR", m_dir.c_str(), 1);
  }
  void TearDown() override {
    if (m_previous.empty())
      unsetenv("HIPR_CACHE_DIR");
    else
      setenv("HIPR_CACHE_DIR", m_previous.c_str(), 1);
  }
  std::vector<std::filesystem::path> cache_files() const {
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(m_dir / "shaders"))
      files.push_back(entry.path());
    return files;
  }
  std::filesystem::path m_dir;
  std::string m_previous;
};

TEST_F(ShaderCache, CompilesOnceThenReusesTheCache) {
  const vk::CompiledShader first = vk::compile_compute_shader("trace_tiles.comp", {});
  EXPECT_FALSE(first.from_cache);
  ASSERT_GT(first.spirv.size(), 100u);
  EXPECT_EQ(first.spirv[0], 0x07230203u);
  const vk::CompiledShader second = vk::compile_compute_shader("trace_tiles.comp", {});
  EXPECT_TRUE(second.from_cache);
  EXPECT_EQ(first.spirv, second.spirv);
  EXPECT_EQ(cache_files().size(), 1u);
}

TEST_F(ShaderCache, DefinesAreAPartOfTheKey) {
  vk::compile_compute_shader("trace_tiles.comp", {});
  const vk::CompiledShader specialized =
      vk::compile_compute_shader("trace_tiles.comp", {{"HIPR_TEST_DEFINE", "1"}});
  EXPECT_FALSE(specialized.from_cache);
  EXPECT_EQ(cache_files().size(), 2u);
}

TEST_F(ShaderCache, CorruptEntryIsRecompiled) {
  vk::compile_compute_shader("trace_tiles.comp", {});
  for (const auto& file : cache_files()) std::ofstream(file, std::ios::trunc) << "not spir-v";
  const vk::CompiledShader again = vk::compile_compute_shader("trace_tiles.comp", {});
  EXPECT_FALSE(again.from_cache);
  EXPECT_EQ(again.spirv[0], 0x07230203u);
}

TEST(ShaderCompiler, ErrorsNameTheShader) {
  try {
    vk::compile_compute_shader("no_such_kernel.comp", {});
    FAIL() << "expected an error";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_kernel.comp"), std::string::npos);
  }
}

// Every float add and multiply of a compiled kernel carries NoContraction: no driver fuses them
// into FMAs differently in two variants of a kernel (vk/spirv_no_contraction.h).
TEST(ShaderCompiler, ArithmeticIsNeverContracted) {
  const std::vector<uint32_t> spirv = vk::compile_compute_shader("display.comp", {}).spirv;
  std::set<uint32_t> arithmetic, no_contraction;
  for (size_t at = 5; at < spirv.size(); at += spirv[at] >> 16) {
    const uint32_t opcode = spirv[at] & 0xffffu;
    if (opcode == 129 || opcode == 131 || opcode == 133 || opcode == 136)
      arithmetic.insert(spirv[at + 2]);  // FAdd FSub FMul FDiv
    if (opcode == 71 && spirv[at + 2] == 42)
      no_contraction.insert(spirv[at + 1]);  // OpDecorate NoContraction
  }
  EXPECT_GT(arithmetic.size(), 3u) << "the display kernel does float arithmetic";
  for (uint32_t id : arithmetic) EXPECT_TRUE(no_contraction.count(id)) << "%" << id;
}

TEST(Device, MissingDeviceIsAClearError) {
  vk::ContextOptions options;
  options.preferred_device = "no such device anywhere";
  try {
    vk::Context ctx(options);
    FAIL() << "expected an error";
  } catch (const std::exception& e) {
    // It names what was asked for and what is there.
    EXPECT_NE(std::string(e.what()).find("'no such device anywhere'"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find(test::context().device_name()), std::string::npos)
        << e.what();
  }
}

TEST(Device, ForcedRayQueriesOnADeviceWithoutThemIsAClearError) {
  if (test::context().has_ray_queries())
    GTEST_SKIP() << test::context().device_name() << " has ray queries";
  vk::ContextOptions options;
  options.traversal = vk::Traversal::RayQuery;
  try {
    vk::Context ctx(options);
    FAIL() << "expected an error";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("ray queries"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace hipr
