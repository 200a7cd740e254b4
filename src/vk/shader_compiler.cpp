#include "vk/shader_compiler.h"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <system_error>

#include "core/error.h"
#include "core/file_util.h"
#include "core/hash.h"
#include "core/log.h"
#include "vk/embedded_shaders.h"
#include "vk/spirv_no_contraction.h"

namespace hipr::vk {
namespace fs = std::filesystem;
namespace {

// Bump when the compile options change, so old cache entries are ignored.
constexpr const char* kCompilerConfig = "glslang-vk1.2-spv1.5-O-nocontraction-v2";

const std::map<std::string, std::string_view>& shader_sources() {
  static const auto sources = [] {
    std::map<std::string, std::string_view> map;
    for (const EmbeddedShaderFile& file : embedded_shader_files())
      map.emplace(file.path, file.text);
    return map;
  }();
  return sources;
}

std::string_view find_source(const std::string& path) {
  const auto& sources = shader_sources();
  const auto it = sources.find(path);
  if (it == sources.end()) throw InternalError("shader source not found: " + path);
  return it->second;
}

// Resolves #include "x" against the including file's folder, then the shaders/ root.
class EmbeddedIncluder : public glslang::TShader::Includer {
 public:
  IncludeResult* includeLocal(const char* header, const char* includer, size_t depth) override {
    const fs::path from = fs::path(includer).parent_path();
    for (const fs::path& candidate :
         {(from / header).lexically_normal(), fs::path(header).lexically_normal()}) {
      const auto& sources = shader_sources();
      const auto it = sources.find(candidate.generic_string());
      if (it != sources.end())
        return new IncludeResult(it->first, it->second.data(), it->second.size(), nullptr);
    }
    (void)depth;
    return nullptr;
  }
  IncludeResult* includeSystem(const char* header, const char* includer, size_t depth) override {
    return includeLocal(header, includer, depth);
  }
  void releaseInclude(IncludeResult* result) override { delete result; }
};

std::string make_preamble(const ShaderDefines& defines) {
  std::string preamble;
  for (const auto& [name, value] : defines) preamble += "#define " + name + " " + value + "\n";
  return preamble;
}

std::string cache_key(const std::string& entry, const std::string& preamble) {
  Hasher hasher;
  hasher.add(kCompilerConfig).add(entry).add(preamble);
  // Every embedded file takes part: any shader edit invalidates the cache, never a stale kernel.
  for (const auto& [path, text] : shader_sources()) hasher.add(path).add(text);
  return hasher.hex();
}

std::vector<uint32_t> read_cached(const fs::path& file) {
  std::error_code ec;
  if (file.empty() || !fs::is_regular_file(file, ec)) return {};
  try {
    const auto bytes = read_file_bytes(file);
    if (bytes.size() < 4 || bytes.size() % 4 != 0) return {};
    std::vector<uint32_t> words(bytes.size() / 4);
    std::memcpy(words.data(), bytes.data(), bytes.size());
    if (words[0] != 0x07230203u) return {};  // SPIR-V magic: a truncated/foreign file is ignored
    return words;
  } catch (const std::exception&) {
    return {};
  }
}

void write_cached(const fs::path& file, const std::vector<uint32_t>& spirv) {
  try {
    fs::create_directories(file.parent_path());
    write_atomically(file, [&](const fs::path& temp) {
      std::ofstream out(temp, std::ios::binary);
      out.write(reinterpret_cast<const char*>(spirv.data()), std::streamsize(spirv.size() * 4));
      if (!out) throw InternalError("short write");
    });
  } catch (const std::exception& e) {
    log::warn(std::string("shader cache not written: ") + e.what());
  }
}

std::vector<uint32_t> compile(const std::string& entry, const std::string& preamble) {
  static std::once_flag init;
  std::call_once(init, [] {
    glslang::InitializeProcess();
    std::atexit([] { glslang::FinalizeProcess(); });
  });

  const std::string_view source = find_source(entry);
  const char* text = source.data();
  const int length = int(source.size());
  const char* name = entry.c_str();

  glslang::TShader shader(EShLangCompute);
  shader.setStringsWithLengthsAndNames(&text, &length, &name, 1);
  shader.setPreamble(preamble.c_str());
  shader.setEnvInput(glslang::EShSourceGlsl, EShLangCompute, glslang::EShClientVulkan, 100);
  shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_2);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_5);
  EmbeddedIncluder includer;
  const EShMessages messages = EShMessages(EShMsgSpvRules | EShMsgVulkanRules);
  if (!shader.parse(GetDefaultResources(), 460, false, messages, includer))
    throw InternalError("shader " + entry + " does not compile:\n" + shader.getInfoLog());

  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(messages))
    throw InternalError("shader " + entry + " does not link:\n" + program.getInfoLog());

  std::vector<uint32_t> spirv;
  glslang::SpvOptions options;
  options.disableOptimizer = false;
  options.optimizeSize = false;
  options.validate = false;
  glslang::GlslangToSpv(*program.getIntermediate(EShLangCompute), spirv, &options);
  forbid_contraction(spirv);  // the same rounding in every variant of a kernel, on every driver
  return spirv;
}

}  // namespace

fs::path shader_cache_dir() {
  if (const char* dir = std::getenv("HIPR_CACHE_DIR"); dir && *dir)
    return fs::path(dir) / "shaders";
  if (const char* dir = std::getenv("XDG_CACHE_HOME"); dir && *dir)
    return fs::path(dir) / "hipr" / "shaders";
  if (const char* home = std::getenv("HOME"); home && *home)
    return fs::path(home) / ".cache" / "hipr" / "shaders";
  return {};
}

CompiledShader compile_compute_shader(const std::string& entry, const ShaderDefines& defines) {
  const std::string preamble = make_preamble(defines);
  const fs::path dir = shader_cache_dir();
  const fs::path file = dir.empty() ? fs::path() : dir / (cache_key(entry, preamble) + ".spv");
  if (auto cached = read_cached(file); !cached.empty()) return {std::move(cached), true};
  CompiledShader result{compile(entry, preamble), false};
  if (!file.empty()) write_cached(file, result.spirv);
  return result;
}

}  // namespace hipr::vk
