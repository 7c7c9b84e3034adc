# scripts/lib.sh: shared by scripts/demo and scripts/test: install what is missing, build.
# Sourced, not run. Idempotent: a second run skips packages present and rebuilds incrementally.

TP_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
TP_BUILD=${TP_BUILD:-$TP_ROOT/build}
TP_JOBS=${TP_JOBS:-$(nproc)}

# Debian 12 packages the project builds, tests and demos with.
TP_PACKAGES=(
  build-essential cmake ninja-build pkg-config git
  libusb-1.0-0-dev libgpiod-dev gpiod usbutils
  libopenimageio-dev openimageio-tools
  libcgal-dev libeigen3-dev
  libspdlog-dev nlohmann-json3-dev libcli11-dev libsqlite3-dev sqlite3 libzip-dev libmd-dev zlib1g-dev
  liblcms2-dev icc-profiles-free colord-data libgs10-common ghostscript
  libgtest-dev libgmock-dev libbenchmark-dev
  libumockdev-dev umockdev
  python3
  clang libclang-rt-14-dev
  clang-format  # scripts/check-format: the lines a change touches follow .clang-format
  python3-ezdxf python3-jsonschema pngcheck librsvg2-bin libtiff-tools
  libtiff-dev   # separated TIFFs (InkSet, InkNames) for separations and the simulator's fabric
  assimp-utils  # independent OBJ/MTL reader for the garment.obj test
  libjs-three chromium chromium-driver python3-selenium  # browser viewer check of garment.obj
  firefox-esr  # the operator console's check in Firefox (driven over Marionette; docs/console.md)
  argyll  # printctl calibrate: targen, colprof, profcheck (docs/colour.md)
  libcpp-httplib-dev libssl-dev openssl  # printd's HTTP API (TLS via OpenSSL); the tests make a cert
  libfreetype-dev libharfbuzz-dev fonts-dejavu-core  # text design layers (FreeType, HarfBuzz, DejaVu)
  systemd dpkg-dev wrk  # systemd-analyze verify and dpkg-shlibdeps for the .deb test; HTTP load figures
  libpugixml-dev  # the FreeSewing SVG importer's XML parser
)

tp_log() { printf '\033[1m==> %s\033[0m\n' "$*" >&2; }

# Runs a command as root: directly when root, through sudo otherwise.
tp_as_root() {
  if [ "$(id -u)" -eq 0 ]; then "$@"
  elif command -v sudo >/dev/null 2>&1; then sudo "$@"
  else echo "error: need root (or sudo) to run: $*" >&2; return 1
  fi
}

# Installs the packages that are not installed yet; does nothing when all are there.
tp_install_deps() {
  local missing=()
  for p in "${TP_PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if [ ${#missing[@]} -eq 0 ]; then
    tp_log "packages: all ${#TP_PACKAGES[@]} present"
    return 0
  fi
  tp_log "packages: installing ${missing[*]}"
  tp_as_root env DEBIAN_FRONTEND=noninteractive apt-get update -q
  tp_as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
}

# Configures (once) and builds everything into $TP_BUILD (executables in $TP_BUILD/bin).
tp_build() {
  if [ ! -f "$TP_BUILD/build.ninja" ]; then
    tp_log "configure: $TP_BUILD"
    cmake -S "$TP_ROOT" -B "$TP_BUILD" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
  fi
  tp_log "build: $TP_JOBS jobs"
  cmake --build "$TP_BUILD" -j "$TP_JOBS"
}

# Builds the libFuzzer targets with clang into $TP_BUILD/fuzz (only the fuzz targets and the
# sources they name), so the suite can run each for a few seconds.
tp_build_fuzz() {
  local dir="$TP_BUILD/fuzz"
  if [ ! -f "$dir/build.ninja" ]; then
    tp_log "configure fuzz build (clang, libFuzzer): $dir"
    cmake -S "$TP_ROOT" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DTP_FUZZ=ON -DTP_BUILD_BENCH=OFF
  fi
  tp_log "build fuzz targets"
  cmake --build "$dir" -j "$TP_JOBS" --target fuzz_all
}
