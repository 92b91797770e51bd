#!/usr/bin/env bash
# Installs the peers the bench/ scripts compare lispcad with, on Debian/Ubuntu: Lua 5.4 and
# Guile 3.0 (bench/run-lang.sh, bench/run-startup.sh). CPython's ezdxf, numpy and trimesh come
# from the tests' .venv (.ci/setup). A peer that is missing is left out of the tables.
set -euo pipefail
sudo=""
if [[ $(id -u) -ne 0 ]]; then sudo=sudo; fi
if ! $sudo apt-get install -y --no-install-recommends lua5.4 guile-3.0; then
  $sudo apt-get update
  $sudo apt-get install -y --no-install-recommends lua5.4 guile-3.0
fi
