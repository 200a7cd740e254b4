// glTF 2.0 -> Scene. Order of defence: container and JSON checks first (our code), then
// tinygltf parses with sandboxed file access, then every index and accessor is validated as it
// is converted. Anything wrong with the input is an InputError naming the object at fault.
#include <stb_image.h>
#include <tiny_gltf.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <glm/gtc/type_ptr.hpp>

#include "core/error.h"
#include "core/file_util.h"
#include "core/log.h"
#include "hipr/edits.h"
#include "hipr/scene_loader.h"
#include "image/builtin_environments.h"
#include "scene/decoded_texture.h"
#include "scene/default_camera.h"
#include "scene/glb_container.h"
#include "scene/gltf_accessors.h"
#include "scene/gltf_draco.h"
#include "scene/gltf_hipr_extras.h"
#include "scene/gltf_image_decode.h"
#include "scene/gltf_instancing.h"
#include "scene/gltf_materials.h"
#include "scene/gltf_meshopt.h"
#include "scene/gltf_node_transform.h"
#include "scene/gltf_parser_input.h"
#include "scene/gltf_pose.h"
#include "scene/gltf_precheck.h"
#include "scene/gltf_sandbox.h"
#include "scene/gltf_variants.h"
#include "scene/mesh_processing.h"
#include "scene/scene_limits.h"

namespace hipr {
namespace fs = std::filesystem;

namespace {

// EXT_mesh_gpu_instancing instances in one scene (each a node and a TLAS entry).
constexpr size_t kMaxGpuInstances = size_t(1) << 20;

// Decodes images with stb, but a broken image becomes a warning and a fallback texture, not a
// failed load. So does one whose size (read from its header first) is beyond the limits, or
// would take the scene's images beyond theirs (`user`: the pixels decoded so far).
bool lenient_image_loader(tinygltf::Image* image, const int index, std::string* err,
                          std::string* warn, int width, int height, const unsigned char* bytes,
                          int size, void* user) {
  (void)err;
  const auto refuse = [&](const std::string& why) {
    if (warn) *warn += "image " + std::to_string(index) + " " + why + "\n";
    image->image.clear();
    return true;
  };
  size_t& decoded = *static_cast<size_t*>(user);
  if (gltf::needs_extension_decoder(bytes, size_t(std::max(size, 0)))) {  // WebP, AVIF, DDS
    std::string why;
    const size_t budget = std::min(gltf::kMaxImagePixels, gltf::kMaxScenePixels - decoded);
    if (!gltf::decode_extension_image(image, bytes, size_t(size), budget, gltf::kMaxImageSide,
                                      &why))
      return refuse("could not be decoded: " + why);
    decoded += size_t(image->width) * size_t(image->height);
    return true;
  }
  int w = 0, h = 0, channels = 0;
  if (stbi_info_from_memory(bytes, size, &w, &h, &channels)) {
    if (std::string why =
            gltf::texture_size_problem(w, h, gltf::kMaxImagePixels, gltf::kMaxImageSide);
        !why.empty())
      return refuse(why + " (" + std::to_string(gltf::kMaxImageSide) + " a side, " +
                    std::to_string(gltf::kMaxImagePixels) + " pixels): not decoded");
    if (decoded + size_t(w) * size_t(h) > gltf::kMaxScenePixels)
      return refuse("would take the scene's images beyond " +
                    std::to_string(gltf::kMaxScenePixels) + " pixels: not decoded");
    decoded += size_t(w) * size_t(h);
  }
  std::string local_err;
  // (tinygltf reads its own options from the last argument: none.)
  if (tinygltf::LoadImageData(image, index, &local_err, warn, width, height, bytes, size, nullptr))
    return true;
  return refuse("could not be decoded: " + local_err);
}

glm::mat4 node_transform(const tinygltf::Node& node, const std::string& what) {
  if (!node.matrix.empty() && node.matrix.size() != 16)
    throw InputError(what + " has a matrix of " + std::to_string(node.matrix.size()) +
                     " numbers (expected 16)");
  const glm::mat4 m =
      gltf::local_transform(node.matrix, node.translation, node.rotation, node.scale);
  for (int i = 0; i < 16; ++i)
    if (!std::isfinite(glm::value_ptr(m)[i]))
      throw InputError(what + " has a non-finite transform");
  return m;
}

class Converter {
 public:
  Converter(const tinygltf::Model& model, Scene& scene, const std::string& name)
      : m_model(model),
        m_scene(scene),
        m_name(name),
        m_textures(model, scene),
        m_poses(model, name) {}

  void run() {
    convert_materials();
    convert_variant_names();
    convert_meshes();
    convert_cameras();
    convert_lights();
    convert_nodes();
    convert_gpu_instances();
    for (const std::string& ext : m_model.extensionsUsed) m_scene.extensions_used.push_back(ext);
    gltf::warn_unsupported_extensions(m_model.extensionsUsed, m_name);
  }

 private:
  std::string object(const char* kind, size_t index, const std::string& label) const {
    return m_name + ": " + kind + " " + std::to_string(index) +
           (label.empty() ? "" : " ('" + label + "')");
  }

  void convert_materials() {
    for (size_t i = 0; i < m_model.materials.size(); ++i)
      m_scene.materials.push_back(
          gltf::convert_material(m_model.materials[i], i, m_textures, m_name));
    // glTF's default material, for primitives without one (edited and saved: document extras).
    Material fallback;
    fallback.name = "default";
    fallback.params = gltf::default_gltf_material_params();
    gltf::apply_openpbr_extras(m_model.extras, gltf::kDefaultMaterialExtras, fallback.params,
                               m_name);
    m_default_material = uint32_t(m_scene.materials.size());
    m_scene.materials.push_back(fallback);
  }

  void convert_variant_names() { m_scene.material_variants = gltf::variant_names(m_model, m_name); }

  void convert_meshes() {
    for (size_t mi = 0; mi < m_model.meshes.size(); ++mi) {
      const tinygltf::Mesh& source = m_model.meshes[mi];
      Mesh mesh;
      mesh.name = source.name.empty() ? "mesh " + std::to_string(mi) : source.name;
      for (size_t pi = 0; pi < source.primitives.size(); ++pi) {
        const std::string what =
            object("mesh", mi, source.name) + " primitive " + std::to_string(pi);
        if (auto primitive = convert_primitive(mi, source.primitives[pi], what))
          mesh.primitives.push_back(std::move(*primitive));
      }
      mesh.revision = mesh_revision(mesh);
      m_scene.meshes.push_back(std::move(mesh));
    }
  }

  std::optional<MeshPrimitive> convert_primitive(size_t mesh, const tinygltf::Primitive& source,
                                                 const std::string& what) {
    const int mode = source.mode < 0 ? TINYGLTF_MODE_TRIANGLES : source.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        mode != TINYGLTF_MODE_TRIANGLE_FAN) {
      log::warn(what + " draws points or lines; skipped");
      return std::nullopt;
    }
    const auto attribute = [&](const char* name) {
      const auto it = source.attributes.find(name);
      return it == source.attributes.end() ? -1 : it->second;
    };
    if (attribute("POSITION") < 0) {
      log::warn(what + " has no POSITION attribute; skipped");
      return std::nullopt;
    }
    if (source.material >= int(m_model.materials.size()))
      throw InputError(what + " references missing material " + std::to_string(source.material));

    MeshPrimitive p;
    p.material = source.material < 0 ? m_default_material : uint32_t(source.material);
    p.default_material = p.material;
    p.variant_materials =
        gltf::variant_materials(m_model, source, m_scene.material_variants.size(), what);
    p.positions =
        gltf::to_vec3(gltf::read_floats(m_model, attribute("POSITION"), 3, what + " POSITION"));
    if (attribute("NORMAL") >= 0)
      p.normals =
          gltf::to_vec3(gltf::read_floats(m_model, attribute("NORMAL"), 3, what + " NORMAL"));
    if (attribute("TANGENT") >= 0)
      p.tangents =
          gltf::to_vec4(gltf::read_floats(m_model, attribute("TANGENT"), 4, what + " TANGENT"));
    if (attribute("TEXCOORD_0") >= 0)
      p.uvs = gltf::to_vec2(
          gltf::read_floats(m_model, attribute("TEXCOORD_0"), 2, what + " TEXCOORD_0"));
    if (attribute("TEXCOORD_1") >= 0)
      p.uvs1 = gltf::to_vec2(
          gltf::read_floats(m_model, attribute("TEXCOORD_1"), 2, what + " TEXCOORD_1"));
    m_poses.apply(mesh, source, p, what);  // morph targets and skin, as the file poses them
    if (source.indices >= 0) {
      p.indices = gltf::read_indices(m_model, source.indices, what + " indices");
    } else {
      p.indices.resize(p.positions.size());
      for (size_t i = 0; i < p.indices.size(); ++i) p.indices[i] = uint32_t(i);
    }
    if (mode != TINYGLTF_MODE_TRIANGLES) p.indices = triangulate(p.indices, mode);
    complete_primitive(p, what);
    return p;
  }

  void convert_cameras() {
    for (size_t i = 0; i < m_model.cameras.size(); ++i) {
      const tinygltf::Camera& source = m_model.cameras[i];
      Camera camera;
      camera.name = source.name;
      if (source.type == "perspective") {
        const double yfov = source.perspective.yfov;
        if (!std::isfinite(yfov) || yfov <= 0.0 || yfov >= 3.14159)
          throw InputError(object("camera", i, source.name) + " has an invalid yfov");
        camera.yfov = float(yfov);
        camera.znear = float(std::max(source.perspective.znear, 0.0));
      } else {
        log::warn(object("camera", i, source.name) +
                  " is orthographic; rendered as a 45-degree perspective camera");
        camera.yfov = 0.785398f;
      }
      gltf::apply_lens_extras(source.extras, camera, object("camera", i, source.name));
      m_scene.cameras.push_back(camera);
    }
  }

  void convert_lights() {
    for (size_t i = 0; i < m_model.lights.size(); ++i) {
      const tinygltf::Light& source = m_model.lights[i];
      PunctualLight light;
      light.name = source.name.empty() ? "light " + std::to_string(i) : source.name;
      if (source.color.size() >= 3)
        light.color =
            glm::max(glm::vec3(source.color[0], source.color[1], source.color[2]), glm::vec3(0));
      light.intensity = float(source.intensity);
      light.range = float(source.range);
      if (!std::isfinite(light.range) || light.range < 0.0f)
        throw InputError(object("light", i, source.name) + " has a negative or non-finite range");
      if (source.type == "point")
        light.type = LightType::Point;
      else if (source.type == "spot")
        light.type = LightType::Spot;
      else if (source.type == "directional")
        light.type = LightType::Directional;
      else
        throw InputError(object("light", i, source.name) + " has unknown type '" + source.type +
                         "'");
      light.inner_cone = float(source.spot.innerConeAngle);
      light.outer_cone = float(source.spot.outerConeAngle);
      gltf::apply_light_extras(source.extras, light, object("light", i, source.name));
      if (!std::isfinite(light.intensity) || light.intensity < 0 ||
          !std::isfinite(light.color.x + light.color.y + light.color.z))
        throw InputError(object("light", i, source.name) + " has an invalid intensity or colour");
      m_scene.lights.push_back(light);
    }
  }

  void convert_nodes() {
    const size_t count = m_model.nodes.size();
    m_scene.nodes.resize(count);
    m_scene.children.assign(count, {});
    for (size_t i = 0; i < count; ++i) {
      const tinygltf::Node& source = m_model.nodes[i];
      Node& node = m_scene.nodes[i];
      const std::string what = object("node", i, source.name);
      node.name = source.name.empty() ? "#" + std::to_string(i) : source.name;
      node.local = node_transform(source, what);
      node.mesh = checked(source.mesh, m_model.meshes.size(), what, "mesh");
      node.camera = checked(source.camera, m_model.cameras.size(), what, "camera");
      node.visible = visibility(source, what);
      if (const auto it = source.extensions.find("KHR_lights_punctual");
          it != source.extensions.end() && it->second.Has("light")) {
        const tinygltf::Value& light = it->second.Get("light");
        if (!light.IsInt()) throw InputError(what + ": KHR_lights_punctual.light is not an index");
        node.light = checked(light.GetNumberAsInt(), m_model.lights.size(), what, "light");
      }
      for (int child : source.children) {
        const int c = required(child, count, what, "child node");
        if (size_t(c) == i)
          throw InputError(what + " is its own child (cycle in the node hierarchy)");
        if (m_scene.nodes[size_t(c)].parent >= 0)
          throw InputError(what + ": node " + std::to_string(c) +
                           " has more than one parent (node hierarchy must be a tree)");
        m_scene.nodes[size_t(c)].parent = int(i);
        m_scene.children[i].push_back(uint32_t(c));
      }
    }
    // With one parent per node, a cycle is a parent chain longer than the node count.
    for (size_t i = 0; i < count; ++i) {
      size_t steps = 0;
      for (int p = m_scene.nodes[i].parent; p >= 0; p = m_scene.nodes[size_t(p)].parent)
        if (++steps > count)
          throw InputError(object("node", i, m_model.nodes[i].name) +
                           " is part of a cycle in the node hierarchy");
    }
    const int scene = m_model.defaultScene >= 0 ? m_model.defaultScene : 0;
    if (!m_model.scenes.empty()) {
      if (size_t(scene) >= m_model.scenes.size())
        throw InputError(m_name + ": default scene " + std::to_string(scene) + " does not exist");
      const std::string what = m_name + ": scene " + std::to_string(scene);
      for (int root : m_model.scenes[size_t(scene)].nodes) {
        const int r = required(root, count, what, "node");
        if (m_scene.nodes[size_t(r)].parent >= 0)
          throw InputError(what + ": root node " + std::to_string(r) +
                           " is also a child of another node");
        if (std::find(m_scene.root_nodes.begin(), m_scene.root_nodes.end(), uint32_t(r)) !=
            m_scene.root_nodes.end())
          throw InputError(what + " lists node " + std::to_string(r) + " twice");
        m_scene.root_nodes.push_back(uint32_t(r));
      }
    } else {
      // No scenes: render every parentless node (the spec leaves this to the client).
      for (size_t i = 0; i < count; ++i)
        if (m_scene.nodes[i].parent < 0) m_scene.root_nodes.push_back(uint32_t(i));
    }
  }

  // EXT_mesh_gpu_instancing: each instance of a node's mesh becomes a child node "<name>/<k>"
  // (Node::gpu_instance) with the instance's transform and the mesh, which the node itself no
  // longer shows. Instances share the mesh (one BLAS), so a thousand cost a thousand TLAS
  // entries, not a thousand meshes; each can be selected and edited, the node moves them all.
  void convert_gpu_instances() {
    size_t total = 0;
    for (size_t i = 0; i < m_model.nodes.size(); ++i) {
      const tinygltf::Node& source = m_model.nodes[i];
      const auto it = source.extensions.find("EXT_mesh_gpu_instancing");
      if (it == source.extensions.end() || m_scene.nodes[i].mesh < 0) continue;
      const std::string what = object("node", i, source.name) + " EXT_mesh_gpu_instancing";
      const std::vector<glm::mat4> transforms =
          gltf::gpu_instance_transforms(m_model, it->second, what);
      total += transforms.size();
      if (total > kMaxGpuInstances)
        throw InputError(m_name + ": more than " + std::to_string(kMaxGpuInstances) +
                         " instances (EXT_mesh_gpu_instancing; hipr's limit)");
      const int mesh = m_scene.nodes[i].mesh;
      m_scene.nodes[i].mesh = -1;
      for (size_t k = 0; k < transforms.size(); ++k) {
        Node instance;
        instance.name = m_scene.nodes[i].name + "/" + std::to_string(k);
        instance.parent = int(i);
        instance.local = transforms[k];
        instance.mesh = mesh;
        instance.gpu_instance = true;
        m_scene.nodes.push_back(std::move(instance));
        m_scene.children.emplace_back();
        m_scene.children[i].push_back(uint32_t(m_scene.nodes.size() - 1));
      }
      m_scene.gpu_instances.push_back({uint32_t(i), transforms});
    }
  }

  // KHR_node_visibility: "visible": false hides the node and its subtree (Scene::instances).
  static bool visibility(const tinygltf::Node& source, const std::string& what) {
    const auto it = source.extensions.find("KHR_node_visibility");
    if (it == source.extensions.end()) return true;
    if (!it->second.IsObject()) throw InputError(what + ": KHR_node_visibility is not an object");
    if (!it->second.Has("visible")) return true;
    const tinygltf::Value& visible = it->second.Get("visible");
    if (!visible.IsBool())
      throw InputError(what + ": KHR_node_visibility.visible is not a boolean");
    return visible.Get<bool>();
  }

  // An optional reference: -1 means none.
  int checked(int index, size_t count, const std::string& what, const char* kind) const {
    return index == -1 ? -1 : required(index, count, what, kind);
  }

  int required(int index, size_t count, const std::string& what, const char* kind) const {
    if (index < 0 || size_t(index) >= count)
      throw InputError(what + " references missing " + kind + " " + std::to_string(index));
    return index;
  }

  const tinygltf::Model& m_model;
  Scene& m_scene;
  std::string m_name;
  gltf::TextureTable m_textures;
  gltf::MeshPoses m_poses;
  uint32_t m_default_material = 0;
};

}  // namespace

Scene load_scene(const fs::path& path, const SceneLoadOptions& options) {
  const std::string name = path.filename().string();
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError("scene file not found: " + path.string());
  if (!fs::is_regular_file(path, ec))
    throw InputError("scene path is not a file: " + path.string());
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  if (extension != ".gltf" && extension != ".glb")
    throw InputError(path.string() + ": unsupported scene format (expected .gltf or .glb)");

  const std::vector<unsigned char> bytes = read_file_bytes(path);
  if (bytes.empty()) throw InputError(name + ": invalid glTF: file is empty");
  const bool glb = extension == ".glb" || gltf::looks_like_glb(bytes);
  if (glb) gltf::check_glb_container(bytes, name);
  gltf::precheck_json(gltf::json_text(bytes, glb), name);
  const gltf::ParserInput input = gltf::prepare_parser_input(bytes, glb, name);
  const std::vector<unsigned char>& parsed = input.rewritten ? *input.rewritten : bytes;

  const fs::path folder = fs::absolute(path).parent_path();
  gltf::Sandbox sandbox(folder);
  sandbox.hasher().add(bytes.data(), bytes.size());
  tinygltf::FsCallbacks callbacks;
  callbacks.user_data = &sandbox;
  callbacks.FileExists = [](const std::string& file, void* user) {
    return static_cast<gltf::Sandbox*>(user)->exists(file);
  };
  callbacks.ExpandFilePath = [](const std::string& file, void*) {
    return file;
  };  // never shell-expand
  callbacks.ReadWholeFile = [](std::vector<unsigned char>* out, std::string* err,
                               const std::string& file, void* user) {
    return static_cast<gltf::Sandbox*>(user)->read(out, err, file);
  };
  callbacks.WriteWholeFile = [](std::string* err, const std::string&,
                                const std::vector<unsigned char>&, void*) {
    if (err) *err = "writing is disabled while loading";
    return false;
  };

  tinygltf::TinyGLTF parser;
  parser.SetFsCallbacks(callbacks);
  size_t decoded_pixels = 0;
  parser.SetImageLoader(&lenient_image_loader, &decoded_pixels);
  tinygltf::Model model;
  std::string err, warn;
  const std::string base = folder.string();
  const bool ok = glb ? parser.LoadBinaryFromMemory(&model, &err, &warn, parsed.data(),
                                                    unsigned(parsed.size()), base)
                      : parser.LoadASCIIFromString(&model, &err, &warn,
                                                   reinterpret_cast<const char*>(parsed.data()),
                                                   unsigned(parsed.size()), base);
  const auto first_line = [](std::string text) {
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
    const size_t newline = text.find('\n');
    return newline == std::string::npos ? text : text.substr(0, newline);
  };
  if (!ok) throw InputError(name + ": " + (err.empty() ? "invalid glTF" : first_line(err)));
  for (size_t start = 0; start < warn.size();) {
    const size_t end = warn.find('\n', start);
    const std::string line =
        warn.substr(start, end == std::string::npos ? std::string::npos : end - start);
    if (!line.empty()) log::warn(name + ": " + line);
    if (end == std::string::npos) break;
    start = end + 1;
  }

  gltf::decode_meshopt_views(model, input.fallbacks, name);  // before Draco: it may read them
  gltf::decode_draco_primitives(model, input.draco_indices, name);
  gltf::validate_all_accessors(model, name);
  gltf::check_scene_elements(model, name);
  Scene scene;
  scene.source = path;
  Converter(model, scene, name).run();
  scene.loaded_node_count = scene.nodes.size();
  scene.loaded_light_count = scene.lights.size();
  for (const Mesh& mesh : scene.meshes) scene.loaded_mesh_revisions.push_back(mesh.revision);
  if (!options.camera.empty()) scene.active_camera = int(find_camera_node(scene, options.camera));
  if (!options.variant.empty())
    select_material_variant(scene, find_material_variant(scene, options.variant));
  fix_default_camera(scene);  // the view as loaded: edits move objects, not it
  const std::string choice = options.environment.string();
  const SceneLighting lighting = scene_lighting(scene);
  if (choice == kStudioEnvironmentName ||
      (choice == kAutoEnvironment && !lighting.lights_itself())) {
    scene.environment = make_studio_environment();
    if (choice == kAutoEnvironment)
      log::info(name +
                (lighting.emits() ? " brings no light (its emission is 1 nit at most, a glow)"
                                  : " brings no light") +
                ": lit by the built-in studio environment (--env none for none)");
  } else if (!choice.empty() && choice != kAutoEnvironment) {
    scene.environment = make_environment(options.environment, options.sky);
  }
  if (scene.environment) {
    scene.environment->intensity = options.environment_intensity;
    scene.environment->rotation = glm::radians(options.environment_rotation_degrees);
    sandbox.hasher().add(scene.environment->texels.data(),
                         scene.environment->texels.size() * sizeof(glm::vec3));
  } else if (choice == kNoEnvironment && !lighting.emits()) {
    // (Only when asked for by name: the library's default, empty, is silent.)
    log::warn(
        name +
        ": nothing in the scene emits light and there is no environment: the image will be black "
        "(--env studio lights it)");
  }
  check_scene_limits(scene, name);  // before anything derives boxes, powers or a view from it
  scene.content_hash = sandbox.hasher().hex();
  return scene;
}

}  // namespace hipr
