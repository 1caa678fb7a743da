#!/usr/bin/env bash
# Installs every Debian package the build, tests, fuzzers and benchmarks need.
# Idempotent: when everything is present it prints nothing and touches nothing.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config clang
  libeigen3-dev libboost-dev libfreetype-dev libcairo2-dev libpng-dev
  libusb-1.0-0-dev libcli11-dev nlohmann-json3-dev libpolyclipping-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libsqlite3-dev sqlite3 libpq-dev postgresql   # serial store: SQLite (default) and PostgreSQL (tests start a private server)
  libcpp-httplib-dev                            # the station's HTTP + JSON interface (marker serve --http)
  libmodbus-dev python3-pymodbus                # Modbus TCP (marker serve --modbus) and the independent client its tests drive
  python3-serial-asyncio                        # pymodbus.client imports it (Debian only recommends it)
  nodejs                                        # parses the operator page's script (StationHttp test)
  chromium chromium-driver                      # the operator page in a real browser (StationBrowser test, WebDriver)
  libssl-dev                                    # SHA-256 of job files in the audit log (libcrypto)
  libhowardhinnant-date-dev tzdata              # time zones for dates, shifts and counter resets
  libzint-dev libdmtx-dev libzbar-dev libzxing-dev  # 2D codes: zint encodes; ZXing-C++, libdmtx and ZBar decode the simulated mark
  umockdev libumockdev-dev                      # the emulated LMC board behind real libusb (usbfs ioctls)
  hershey-fonts-data librecad-data
  fonts-dejavu-core fonts-liberation2           # TrueType outlines for the fill tests (DejaVu Sans, Liberation Sans)
  python3-fonttools                             # writes the outline-font fixtures (tests/fonts/data/outline/make_fixtures.py)
  libpython3.11 libedit2 libtirpc3   # runtime of LinuxCNC's rs274 (G-code validator, fetch_rs274.sh)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if ((${#missing[@]})); then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  echo "setup: installing ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# The CNC tests validate every G-code program with LinuxCNC's rs274, unpacked (not installed) here.
"$(dirname "${BASH_SOURCE[0]}")/fetch_rs274.sh"
