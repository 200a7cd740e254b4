#include "app/viewer/ui_layer.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_vulkan.h>

#include <algorithm>

#include "core/error.h"
#include "vk/check.h"

namespace hipr::viewer {
namespace {

// The backend reports Vulkan results through this hook: every result goes through VK_CHECK.
void check_vk_result(VkResult result) {
  if (result != VK_SUCCESS) VK_CHECK(result);
}

}  // namespace

UiLayer::UiLayer(const Window& window, const vk::Context& ctx, const vk::UiPass& pass,
                 const vk::Presenter& presenter)
    : m_window(window) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // the viewer writes nothing the user did not ask for
  ImGui::StyleColorsDark();
  if (!window.headless()) ImGui_ImplGlfw_InitForVulkan(window.handle(), true);

  ImGui_ImplVulkan_InitInfo info{};
  info.Instance = ctx.instance();
  info.PhysicalDevice = ctx.physical_device();
  info.Device = ctx.device();
  info.QueueFamily = ctx.queue_family();
  info.Queue = ctx.queue();
  info.DescriptorPool = pass.descriptor_pool();
  info.MinImageCount = std::max(2u, presenter.min_image_count());
  info.ImageCount = std::max(info.MinImageCount, presenter.image_count());
  info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
  info.CheckVkResultFn = check_vk_result;
  if (!ImGui_ImplVulkan_Init(&info, pass.render_pass())) {
    if (!window.headless()) ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    throw InternalError("cannot initialise the UI's Vulkan backend");
  }
  ctx.submit_and_wait([](VkCommandBuffer cmd) { ImGui_ImplVulkan_CreateFontsTexture(cmd); });
  ImGui_ImplVulkan_DestroyFontUploadObjects();
}

UiLayer::~UiLayer() {
  ImGui_ImplVulkan_Shutdown();
  if (!m_window.headless()) ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

void UiLayer::new_frame(const std::vector<KeyPress>& presses) {
  ImGui_ImplVulkan_NewFrame();
  ImGuiIO& io = ImGui::GetIO();
  if (m_window.headless()) {
    const VkExtent2D size = m_window.framebuffer_size();
    io.DisplaySize = ImVec2(float(size.width), float(size.height));
    io.DeltaTime = std::max(float(m_frame_timer.seconds()), 1e-6f);  // ImGui asserts it is > 0
    m_frame_timer = Timer();
    ImGui::NewFrame();
    return;
  }
  ImGui_ImplGlfw_NewFrame();
  for (int key : m_forced) io.KeysDown[key] = glfwGetKey(m_window.handle(), key) == GLFW_PRESS;
  m_forced.clear();
  // Modifiers are not forced: a person holds Ctrl across frames, and a forced Ctrl would also
  // swallow the characters typed in the same frame.
  for (const KeyPress& press : presses)
    if (press.key >= 0 && press.key < int(IM_ARRAYSIZE(io.KeysDown)) && !io.KeysDown[press.key]) {
      io.KeysDown[press.key] = true;
      m_forced.push_back(press.key);
    }
  ImGui::NewFrame();
}

void UiLayer::render(VkCommandBuffer cmd) {
  ImGui::Render();
  ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd);
}

void UiLayer::set_min_image_count(uint32_t count) {
  ImGui_ImplVulkan_SetMinImageCount(std::max(2u, count));
}

}  // namespace hipr::viewer
