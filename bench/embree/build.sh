#!/usr/bin/env bash
# Builds the Embree side of the scaling benchmark into bench/embree/build/scale (git-ignored),
# installing Embree 3 (Debian's libembree-dev) first if its header is missing.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"

if [ ! -f /usr/include/embree3/rtcore.h ]; then
    echo "installing libembree-dev" >&2
    apt-get install -y libembree-dev || { apt-get update && apt-get install -y libembree-dev; }
fi

mkdir -p "$here/build"
g++ -O3 -march=native -std=c++17 -Wall -Wextra -pthread \
    "$here/scale.cpp" -lembree3 -o "$here/build/scale"
echo "built $here/build/scale" >&2
