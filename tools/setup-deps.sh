#!/usr/bin/env bash
# Installs everything hipr needs to build, test and run on Debian 12 (bookworm).
# Idempotent: re-running it changes nothing once the packages are present.
# Lavapipe with VK_KHR_ray_query needs Mesa >= 23, which bookworm only has in bookworm-backports.
set -euo pipefail

if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null; then exec sudo -E bash "$0" "$@"; fi
  echo "setup-deps.sh: must run as root (apt-get)" >&2
  exit 2
fi

export DEBIAN_FRONTEND=noninteractive
backports=/etc/apt/sources.list.d/hipr-bookworm-backports.list

packages=(
  build-essential cmake ninja-build pkg-config python3
  libvulkan-dev vulkan-validationlayers vulkan-tools
  glslang-dev glslang-tools spirv-tools
  libglfw3-dev libglm-dev libtinygltf-dev nlohmann-json3-dev libstb-dev
  libdraco-dev libmeshoptimizer-dev libheif-dev libwebp-dev
  libopenimageio-dev openimageio-tools libimath-dev libopenexr-dev
  libimgui-dev libcli11-dev libgtest-dev
  xvfb xauth python3-matplotlib
  clang libclang-rt-14-dev clang-format
)

have_all() {
  local status
  status=$(dpkg-query -W -f='${Status}\n' "${packages[@]}" mesa-vulkan-drivers 2>/dev/null) || return 1
  [ "$(grep -c 'install ok installed' <<<"$status")" -eq $((${#packages[@]} + 1)) ] || return 1
  # The Mesa from bookworm (22.x) has no ray queries: insist on the backported one.
  local mesa
  mesa=$(dpkg-query -W -f='${Version}' mesa-vulkan-drivers)
  dpkg --compare-versions "$mesa" ge 23
}

# The Khronos glTF-Validator (npm package gltf-validator) for the tests of saved scenes, and
# glTF-Transform (@gltf-transform/cli) that writes the compressed copies the loader's tests read,
# both pinned by tools/package-lock.json; the tests skip without them, so a failure only warns.
# node and npm come from Debian's packages when the machine has none (one installed is kept).
install_gltf_validator() {
  local tools
  tools="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
  if [ -f "$tools/node_modules/gltf-validator/package.json" ] &&
    [ -f "$tools/node_modules/@gltf-transform/cli/package.json" ]; then
    echo "setup-deps: gltf-validator and gltf-transform present"
    return 0
  fi
  if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
    if ! { apt-get update -q && apt-get install -y -q --no-install-recommends nodejs npm; }; then
      echo "setup-deps: warning: could not install nodejs/npm; the glTF validation test will skip" >&2
      return 0
    fi
  fi
  if ! (cd "$tools" && npm ci --no-audit --no-fund --loglevel=error); then
    echo "setup-deps: warning: npm ci in tools/ failed; the glTF validation test will skip" >&2
  fi
}

if have_all; then
  echo "setup-deps: all packages present"
else
  if ! grep -rqs 'bookworm-backports' /etc/apt/sources.list /etc/apt/sources.list.d/; then
    echo "deb http://deb.debian.org/debian bookworm-backports main" >"$backports"
  fi

  apt-get update -q
  apt-get install -y -q --no-install-recommends "${packages[@]}"
  apt-get install -y -q --no-install-recommends -t bookworm-backports mesa-vulkan-drivers
  have_all || { echo "setup-deps: mesa-vulkan-drivers from bookworm-backports did not install" >&2; exit 1; }
  echo "setup-deps: done"
fi

# The ImGui backends build from sources libimgui-dev ships under /usr/share/doc, which slim
# images (debian:bookworm-slim) tell dpkg to leave out: let that folder in and reinstall.
imgui_backends=/usr/share/doc/libimgui-dev/examples/backends
if [ ! -f "$imgui_backends/imgui_impl_glfw.cpp" ] || [ ! -f "$imgui_backends/imgui_impl_vulkan.cpp" ]; then
  echo "path-include=$imgui_backends/*" >/etc/dpkg/dpkg.cfg.d/hipr-imgui-backends
  apt-get update -q && apt-get install -y -q --reinstall libimgui-dev
  [ -f "$imgui_backends/imgui_impl_vulkan.cpp" ] || { echo "setup-deps: $imgui_backends is still missing" >&2; exit 1; }
fi
install_gltf_validator || true
