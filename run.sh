#!/usr/bin/env bash
# One entry point for a fresh Debian 12 machine: installs the Debian packages the project needs
# (only the missing ones), configures and builds in Release, then runs the job asked for.
#   ./run.sh demo    build, then render the fighter demo (PNG frames, contact sheet, GIF, timing)
#   ./run.sh test    build, then run the whole test suite (ctest)
#   ./run.sh bench   build, then run the benchmark programs
set -euo pipefail
cd "$(dirname "$0")"

usage() {
  sed -n '2,6p' "$0" | sed 's/^# \{0,1\}//'
}

PACKAGES=(
  cmake g++ make pkg-config
  libosmesa6-dev libgl-dev libegl-dev libegl-mesa0 libgl1-mesa-dri
  libglm-dev libopenimageio-dev openimageio-tools
  libgtest-dev libgmock-dev
  libcli11-dev nlohmann-json3-dev libtinyobjloader-dev libembree-dev
  libsdl2-dev xvfb xauth xdotool x11-apps
)

install_missing_packages() {
  local missing=()
  for package in "${PACKAGES[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
      missing+=("$package")
    fi
  done
  if [ ${#missing[@]} -eq 0 ]; then
    return
  fi
  echo "run.sh: installing ${missing[*]}"
  local sudo=()
  if [ "$(id -u)" -ne 0 ]; then
    if command -v sudo >/dev/null; then sudo=(sudo); else
      echo "run.sh: need root (or sudo) to install: ${missing[*]}" >&2
      exit 1
    fi
  fi
  "${sudo[@]}" apt-get update -q
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
}

build() {
  install_missing_packages
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > build.log 2>&1 || { cat build.log; exit 1; }
  cmake --build build -j"$(nproc)" >> build.log 2>&1 || { tail -50 build.log; exit 1; }
  echo "run.sh: built in build/ (log: build.log)"
}

# Mesa's shader cache would otherwise write to ~/.cache; it changes no pixel.
export MESA_SHADER_CACHE_DISABLE=${MESA_SHADER_CACHE_DISABLE:-true}

case "${1:-}" in
  demo)
    build
    shift
    ./build/src/glideshadows demo --frames 96 --out out/demo --contact-sheet --gif "$@"
    echo "run.sh: frames in out/demo/ (frame_NNNN.png), out/demo/contact_sheet.png, out/demo/fight.gif"
    ;;
  test)
    build
    ctest --test-dir build --output-on-failure -j2
    ;;
  bench)
    build
    ./build/bench/shim_bench
    ./build/bench/demo_bench
    ;;
  -h|--help|help)
    usage
    ;;
  *)
    usage >&2
    exit 2
    ;;
esac
