#!/usr/bin/env bash
# Fetches the Debian source packages the web build compiles for WebAssembly (SDL2, SDL2_ttf,
# FreeType, Dear ImGui) into DIR/src, through a private apt configuration under DIR/apt: its
# deb-src entries are derived from the machine's own apt sources (the same archives, for this
# release), so the system's apt setup is neither read for writing nor changed.
#   scripts/web/fetch-sources.sh DIR
set -euo pipefail
dir=$(realpath -m "$1")
apt_dir=$dir/apt
src_dir=$dir/src
packages=(libsdl2 libsdl2-ttf freetype imgui)

if [[ -f $src_dir/.complete ]]; then exit 0; fi

codename=$(. /etc/os-release && echo "${VERSION_CODENAME:-}")
[[ -n $codename ]] || { echo "error: /etc/os-release names no release codename" >&2; exit 1; }

mkdir -p "$apt_dir/sources.list.d" "$apt_dir/lists/partial" "$apt_dir/cache/archives/partial"
rm -f "$apt_dir/sources.list.d/"*
# deb822 files (*.sources): each stanza of Types "deb" for this release, as "deb-src".
for f in /etc/apt/sources.list.d/*.sources; do
  [[ -f $f ]] || continue
  awk -v codename="$codename" '
    function flush() {
      if (stanza != "" && isdeb && ours) { sub(/\n$/, "", stanza); print stanza "\n" }
      stanza = ""; isdeb = 0; ours = 0
    }
    /^[[:space:]]*$/ { flush(); next }
    /^#/ { next }
    /^Types:/ { isdeb = ($0 ~ /[[:space:]]deb([[:space:]]|$)/); stanza = stanza "Types: deb-src\n"; next }
    /^Suites:/ {
      n = split($0, s, /[[:space:]]+/)
      for (i = 2; i <= n; i++) if (s[i] == codename || index(s[i], codename "-") == 1) ours = 1
    }
    { stanza = stanza $0 "\n" }
    END { flush() }' "$f" >>"$apt_dir/sources.list.d/derived.sources"
done
# One-line files (sources.list, *.list): "deb ..." lines for this release, as "deb-src ...".
for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
  [[ -f $f ]] || continue
  awk -v codename="$codename" '
    $1 == "deb" {
      i = 2; if ($2 ~ /^\[/) { while (i <= NF && $i !~ /\]$/) i++; i++ }
      suite = $(i + 1)
      if (suite == codename || index(suite, codename "-") == 1) { $1 = "deb-src"; print }
    }' "$f" >>"$apt_dir/sources.list.d/derived.list"
done
if [[ ! -s $apt_dir/sources.list.d/derived.sources && ! -s $apt_dir/sources.list.d/derived.list ]]; then
  echo "error: no apt source for $codename found to derive deb-src entries from" >&2
  exit 1
fi

apt_opts=(
  -o Dir::Etc::SourceList=/dev/null
  -o "Dir::Etc::SourceParts=$apt_dir/sources.list.d"
  -o "Dir::State::Lists=$apt_dir/lists"
  -o "Dir::Cache=$apt_dir/cache"
  -o APT::Sandbox::User=root
)
echo "Fetching the source packages ${packages[*]}" >&2
apt-get "${apt_opts[@]}" update -qq
rm -rf "$src_dir"
mkdir -p "$src_dir"
(cd "$src_dir" && apt-get "${apt_opts[@]}" source -qq "${packages[@]}" >/dev/null)
touch "$src_dir/.complete"
