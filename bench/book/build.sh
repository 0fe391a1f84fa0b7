#!/usr/bin/env bash
# Builds the C++ of *Ray Tracing: The Next Week* (src/TheNextWeek/ of the book's public
# repository, RayTracing/raytracing.github.io, at a pinned commit), edited by
# bench/book/next_week.patch so that its scene is the spec's random_spheres (README.md here
# lists the edits), for bench/book.py. Nothing of the book's code enters this repository:
# it is fetched into bench/book/build/ (git-ignored) and built there.
#
#   bash bench/book/build.sh                  # fetch from GitHub (git, else a curl tarball)
#   BOOK_REPO=/path/to/clone bash bench/book/build.sh
#                                             # a local clone or bare mirror holding the commit
#                                             # (for machines without access to github.com)
#
# Makes, in bench/book/build/:
#   book-native   g++ -std=c++11 -O3 -DNDEBUG -march=native  (the timed one: ours is native too)
#   book-release  g++ -std=c++11 -O3 -DNDEBUG  (the book's own CMake Release flags, portable)
#   book-count    book-native plus -DRTW_COUNT_RAYS: prints "rays N" on stderr (never timed)
# Each binary renders to stdout (a P3 PPM): `book-native [WIDTH [SPP]] > image.ppm`.
# The fetched files are checked against bench/book/sources.sha256 whichever way they came.
# Needs git (or curl and tar), patch and g++ (CXX overrides it).
set -euo pipefail

COMMIT=d3e5bf95bd10414f840b184e4f57e52e4c54a493 # branch dev, 2024-03-25: see README.md
URL=https://github.com/RayTracing/raytracing.github.io
HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
BUILD=$HERE/build
SRC=$BUILD/src
CXX=${CXX:-g++}
# CMake's Release flags for GCC (the book's README recommends a Release build) and the
# standard its CMakeLists.txt sets (C++11, no GNU extensions).
FLAGS=(-std=c++11 -O3 -DNDEBUG)
PATHS=(src/TheNextWeek src/external/stb_image.h)

die() { echo "bench/book/build.sh: $*" >&2; exit 1; }

for tool in "$CXX" patch sha256sum tar; do
    command -v "$tool" >/dev/null || die "needs $tool, which is not installed"
done

# Copies the pinned commit's files into $SRC from the git repository $1.
from_git() {
    git -C "$1" cat-file -e "$COMMIT^{commit}" 2>/dev/null \
        || die "$1 does not hold commit $COMMIT (fetch it there, or unset BOOK_REPO)"
    git -C "$1" archive "$COMMIT" "${PATHS[@]}" | tar -x -C "$SRC" \
        || die "could not extract ${PATHS[*]} of $COMMIT from $1"
}

fetch() {
    rm -rf "$SRC" "$BUILD/repo"
    mkdir -p "$SRC"
    if [[ -n "${BOOK_REPO:-}" ]]; then
        echo "book: sources of $COMMIT from $BOOK_REPO" >&2
        from_git "$BOOK_REPO"
    elif command -v git >/dev/null && git init -q "$BUILD/repo" \
        && git -C "$BUILD/repo" fetch -q --depth 1 "$URL" "$COMMIT"; then
        # Only this commit's objects: a few MB, not the book's whole history.
        echo "book: fetched $COMMIT from $URL" >&2
        from_git "$BUILD/repo"
        rm -rf "$BUILD/repo"
    else
        rm -rf "$BUILD/repo"
        echo "book: git fetch failed; trying the tarball" >&2
        command -v curl >/dev/null || die "cannot fetch $URL (no curl either)"
        curl -fsSL "$URL/archive/$COMMIT.tar.gz" -o "$BUILD/book.tar.gz" \
            || die "cannot download $URL/archive/$COMMIT.tar.gz (no access to github.com?
  Point BOOK_REPO at a clone or mirror that holds the commit instead.)"
        tar -xzf "$BUILD/book.tar.gz" -C "$SRC" --strip-components=1 \
            "${PATHS[@]/#/raytracing.github.io-$COMMIT/}" \
            || die "the tarball lacks ${PATHS[*]}"
        rm -f "$BUILD/book.tar.gz"
    fi
    (cd "$SRC" && sha256sum --quiet -c "$HERE/sources.sha256") \
        || die "the fetched sources differ from bench/book/sources.sha256"
    (cd "$SRC" && patch -p1 --quiet --forward < "$HERE/next_week.patch") \
        || die "bench/book/next_week.patch does not apply to $COMMIT"
    echo "$COMMIT $(sha256sum < "$HERE/next_week.patch")" > "$BUILD/stamp"
}

mkdir -p "$BUILD"
# Fetch again only if the commit or the patch changed since the last build.
if [[ ! -f "$SRC/src/TheNextWeek/main.cc" \
    || "$(cat "$BUILD/stamp" 2>/dev/null)" != "$COMMIT $(sha256sum < "$HERE/next_week.patch")" ]]; then
    fetch
fi

build() {
    local out=$1; shift
    local line="$CXX ${FLAGS[*]} $* ($("$CXX" --version | head -1))"
    # Compile again only if the sources were fetched since or the command changed.
    if [[ -x "$BUILD/$out" && "$BUILD/$out" -nt "$BUILD/stamp" \
        && "$(cat "$BUILD/$out.cmd" 2>/dev/null)" == "$line" ]]; then
        echo "book: $out is up to date" >&2
        return
    fi
    echo "book: $CXX ${FLAGS[*]} $* -> $out" >&2
    "$CXX" "${FLAGS[@]}" "$@" -I "$SRC/src" -o "$BUILD/$out.tmp" "$SRC/src/TheNextWeek/main.cc" \
        || die "$CXX failed building $out"
    mv "$BUILD/$out.tmp" "$BUILD/$out"
    echo "$line" > "$BUILD/$out.cmd"
}
build book-native -march=native
build book-release
build book-count -march=native -DRTW_COUNT_RAYS
"$CXX" --version | head -1 > "$BUILD/compiler"
echo "book: built $BUILD/book-native, book-release, book-count ($COMMIT)" >&2
