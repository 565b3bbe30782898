#!/usr/bin/env bash
# Proves that contactfx can be installed and used: installs BUILD_DIR into a temporary prefix, then
# builds and runs the consumer project tests/consumer (find_package only, never the source tree) and the
# README's snippet through pkg-config, and runs the installed programs from the prefix.
# Usage: bash scripts/check-install.sh [BUILD_DIR]   (default build; it must be built)
set -euo pipefail
cd "$(dirname "$0")/.."
build="$(realpath "${1:-build}")"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
prefix="$work/prefix"

cmake --install "$build" --prefix "$prefix" >/dev/null
version="$(sed -n 's/^#define CONTACTFX_VERSION_STRING "\(.*\)"$/\1/p' "$prefix/include/contactfx/version.h")"
echo "installed contactfx $version into a temporary prefix"

# Nothing of the source tree may leak in: build the consumer from a copy outside it.
cp -r tests/consumer "$work/consumer"
cmake -S "$work/consumer" -B "$work/consumer-build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
cmake --build "$work/consumer-build" >/dev/null
"$work/consumer-build/consumer" "$version"
"$work/consumer-build/consumer_components" "$prefix/share/contactfx/scenes/grinder.json"
"$work/consumer-build/consumer_render"
# docs/api.md shows the consumer's own find_package line (its version follows the release's).
consumer_line="$(sed -n 's/^\(find_package(contactfx [^)]*)\).*/\1/p' tests/consumer/CMakeLists.txt)"
if ! grep -qF "$consumer_line" docs/api.md; then
  echo "check-install: docs/api.md does not show the consumer's line: $consumer_line" >&2
  exit 1
fi
# An unknown component is refused with a message naming it.
mkdir -p "$work/unknown"
printf 'cmake_minimum_required(VERSION 3.25)\nproject(u LANGUAGES CXX)\nfind_package(contactfx REQUIRED COMPONENTS bogus)\n' \
  > "$work/unknown/CMakeLists.txt"
if cmake -S "$work/unknown" -B "$work/unknown-build" -DCMAKE_PREFIX_PATH="$prefix" >"$work/unknown.log" 2>&1 ||
  ! grep -q 'unknown component "bogus"' "$work/unknown.log"; then
  echo "check-install: find_package(contactfx COMPONENTS bogus) did not fail naming the component" >&2
  cat "$work/unknown.log" >&2
  exit 1
fi
# Without Cairo, an optional render component is not found and the rest configures; a required one fails
# naming Cairo.
mkdir -p "$work/nocairo/pc"
printf 'cmake_minimum_required(VERSION 3.25)\nproject(o LANGUAGES CXX)\nfind_package(contactfx REQUIRED COMPONENTS scene OPTIONAL_COMPONENTS render)\nif(contactfx_render_FOUND OR NOT TARGET contactfx::scene)\n  message(FATAL_ERROR "render found without Cairo, or scene missing")\nendif()\n' \
  > "$work/nocairo/CMakeLists.txt"
if ! PKG_CONFIG_LIBDIR="$work/nocairo/pc" PKG_CONFIG_PATH="" \
  cmake -S "$work/nocairo" -B "$work/nocairo-build" -DCMAKE_PREFIX_PATH="$prefix" >"$work/nocairo.log" 2>&1; then
  echo "check-install: find_package(contactfx OPTIONAL_COMPONENTS render) failed without Cairo" >&2
  cat "$work/nocairo.log" >&2
  exit 1
fi
sed -i 's/OPTIONAL_COMPONENTS render/COMPONENTS render/' "$work/nocairo/CMakeLists.txt"
if PKG_CONFIG_LIBDIR="$work/nocairo/pc" PKG_CONFIG_PATH="" \
  cmake -S "$work/nocairo" -B "$work/nocairo-build2" -DCMAKE_PREFIX_PATH="$prefix" >"$work/nocairo2.log" 2>&1 ||
  ! grep -q 'needs Cairo' "$work/nocairo2.log"; then
  echo "check-install: find_package(contactfx COMPONENTS render) without Cairo did not fail naming Cairo" >&2
  cat "$work/nocairo2.log" >&2
  exit 1
fi
echo "find_package(contactfx): ok"

export PKG_CONFIG_PATH="$prefix/lib/pkgconfig${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}"
# shellcheck disable=SC2046
c++ -O1 "$work/consumer/consumer.cpp" -o "$work/consumer-pc" $(pkg-config --cflags --libs contactfx)
"$work/consumer-pc" "$version"
# shellcheck disable=SC2046
c++ -O1 "$work/consumer/consumer_components.cpp" -o "$work/consumer-components-pc" \
  $(pkg-config --cflags --libs contactfx-render contactfx-scene)
"$work/consumer-components-pc" "$prefix/share/contactfx/scenes/grinder.json"
# The render component alone needs only the core.
# shellcheck disable=SC2046
c++ -O1 "$work/consumer/consumer_render.cpp" -o "$work/consumer-render-pc" $(pkg-config --cflags --libs contactfx-render)
"$work/consumer-render-pc"
# The static libraries are position independent: they link into a shared library (a game's plugin).
# shellcheck disable=SC2046
c++ -shared -fPIC "$work/consumer/consumer_components.cpp" -o "$work/libplugin.so" \
  $(pkg-config --cflags --libs contactfx-render contactfx-scene)
echo "pkg-config: ok"

# The installed programs find the installed scenes wherever the prefix is moved, and name no path of
# the source or build tree.
if [ -x "$prefix/bin/contactfx" ]; then
  mv "$prefix" "$work/moved"
  for tree in "$PWD" "$build"; do
    if grep -q -F "$tree" "$work/moved/bin/contactfx"; then
      echo "check-install: bin/contactfx names $tree" >&2
      exit 1
    fi
  done
  (cd "$work" && env -u CONTACTFX_SCENES "$work/moved/bin/contactfx" --version)
  (cd "$work" && env -u CONTACTFX_SCENES "$work/moved/bin/contactfx" demo --seconds 2 --stats "$work/stats.json" >/dev/null)
  grep -q '"spawned"' "$work/stats.json"
  echo "installed programs: ok"
fi
