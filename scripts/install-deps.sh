#!/usr/bin/env bash
# The one list of system packages recoil needs (Debian 12 / Ubuntu 22.04+).
# Installs only what is missing, through apt-get as root or via sudo.
#   scripts/install-deps.sh          build + test dependencies (ffmpeg included, for --video)
#   scripts/install-deps.sh --farm   also Slurm and munge, for the farm test (make test-farm)
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  ninja-build            # the build tool make uses for new build folders (parallel across targets)
  libeigen3-dev          # Eigen 3.4: all linear algebra
  libembree-dev          # Embree 3: collision queries
  libosmesa6-dev         # OSMesa: offscreen software OpenGL
  libegl-dev             # EGL: the second offscreen backend (--gl egl) ...
  libegl-mesa0           # ... through Mesa's surfaceless platform
  libassimp-dev          # assimp 5: mesh import
  libmeshoptimizer-dev   # meshoptimizer: collision surfaces simplified from fine meshes
  libpng-dev             # PNG read/write
  libstb-dev             # stb_image: the textures of imported meshes (PNG, JPEG, TGA, BMP)
  libfreetype-dev        # the labels of batch contact sheets ...
  fonts-dejavu-core      # ... drawn in DejaVu Sans
  libcli11-dev           # command line
  nlohmann-json3-dev     # scene files, stats
  libgtest-dev           # tests
  libbenchmark-dev       # make bench
  python3                # the hostile-input corpus test (tests/hostile/)
  python3-skimage        # the SSIM test checks recoil's SSIM against scikit-image's
  chromium               # the compare-report test opens report.html in a headless browser
  assimp-testmodels      # a corpus of real, valid and broken mesh files for the import tests
  clang                  # make fuzz: the fuzz targets are built with clang ...
  libclang-rt-14-dev     # ... and linked with its libFuzzer and sanitizer runtimes
  ffmpeg                 # --video: the frames encoded to MP4, WebM or GIF (and the tests of it)
)
case "${1:-}" in
  --farm) packages+=(slurm-wlm munge) ;;
esac

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [[ ${#missing[@]} -eq 0 ]]; then exit 0; fi

echo "install-deps: installing ${missing[*]}" >&2
if [[ $(id -u) -eq 0 ]]; then sudo=(); elif command -v sudo >/dev/null; then sudo=(sudo); else
  echo "install-deps: need root or sudo to install: ${missing[*]}" >&2; exit 1
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq || true
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
