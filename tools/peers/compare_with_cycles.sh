#!/usr/bin/env bash
# Render one frame of a shot in lacrima and in Blender's Cycles (the peer) from the same geometry,
# and compare the two: FLIP and error metrics over the whole frame and over a region (e.g. the
# tear). See docs/peers.md for what is matched, what cannot be, and the results so far.
set -euo pipefail

usage() {
  cat <<'EOF'
usage: tools/peers/compare_with_cycles.sh SHOT [options]

Renders frame F of SHOT twice, with the same camera, lights, environment and materials:
lacrima renders the shot; Cycles renders the frame's geometry as `lacrima export` writes it,
set up by tools/peers/cycles_scene.py. Then `lacrima diff` compares them (Cycles is the
reference A, lacrima the test B), over the whole frame and over --region.

options:
  --frame F            frame to render (default: the shot's first)
  --spp N              samples per pixel for both (default: the shot's)
  --cycles-spp N       Cycles' samples, when it needs more than lacrima (caustics)
  --width W --height H image size (default: the shot's)
  --region X Y W H     also compare this pixel rectangle (top-left X, Y; size W x H)
  --out DIR            where the images and reports go (default: peer-out/<shot name>)
  --threads T          threads for both renderers (default: all cores)
  --cycles-mnee        turn on Cycles' shadow caustics (approximate; off: Cycles path traces them,
                       unbiased, the right reference for light under a tear, but slow to converge)

needs: blender (Debian's package, 3.4) with python3-numpy for its glTF importer, oiiotool,
and a built lacrima (BUILD_DIR=path/to/build, default ./build; or LACRIMA=path/to/lacrima).

example:
  tools/peers/compare_with_cycles.sh tools/peers/shots/tear_on_cheek.json --spp 1024 \
      --region 140 150 80 70
EOF
}

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
lacrima="${LACRIMA:-${BUILD_DIR:-$here/build}/tools/lacrima}"
[ $# -ge 1 ] || { usage >&2; exit 2; }
case "$1" in -h|--help) usage; exit 0 ;; esac
shot="$1"; shift
frame="" spp="" cycles_spp="" width="" height="" region="" out="" threads="$(nproc)" cycles_mnee=()
while [ $# -gt 0 ]; do
  case "$1" in
    --frame) frame="$2"; shift 2 ;;
    --spp) spp="$2"; shift 2 ;;
    --cycles-spp) cycles_spp="$2"; shift 2 ;;
    --width) width="$2"; shift 2 ;;
    --height) height="$2"; shift 2 ;;
    --region) region="$2 $3 $4 $5"; shift 5 ;;
    --out) out="$2"; shift 2 ;;
    --threads) threads="$2"; shift 2 ;;
    --cycles-mnee) cycles_mnee=(--mnee); shift ;;
    -h|--help) usage; exit 0 ;;
    *) echo "compare_with_cycles.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
  esac
done
[ -f "$shot" ] || { echo "compare_with_cycles.sh: $shot: no such shot file" >&2; exit 2; }
[ -x "$lacrima" ] || { echo "compare_with_cycles.sh: no lacrima at $lacrima (build first, or set BUILD_DIR / LACRIMA)" >&2; exit 2; }
command -v blender >/dev/null || { echo "compare_with_cycles.sh: blender not found (apt install blender python3-numpy)" >&2; exit 2; }
command -v oiiotool >/dev/null || { echo "compare_with_cycles.sh: oiiotool not found (apt install openimageio-tools)" >&2; exit 2; }

name="$(basename "$shot" .json)"
out="${out:-peer-out/$name}"
mkdir -p "$out"
if [ -z "$frame" ]; then
  frame="$(python3 "$here/tools/peers/shot_json.py" frame-start "$shot")" || exit 2
fi
size_args=()
[ -n "$width" ] && size_args+=(--width "$width")
[ -n "$height" ] && size_args+=(--height "$height")
spp_args=()
[ -n "$spp" ] && spp_args+=(--spp "$spp")
cycles_spp="${cycles_spp:-$spp}"
cycles_spp_args=()
[ -n "$cycles_spp" ] && cycles_spp_args+=(--spp "$cycles_spp")
frame4="$(printf '%04d' "$frame")"

echo "== geometry of frame $frame (lacrima export)"
"$lacrima" export "$shot" --frames "$frame" --out "$out/geometry.####.glb"

echo "== lacrima"
start=$(date +%s.%N)
"$lacrima" render "$shot" --frames "$frame" "${spp_args[@]}" "${size_args[@]}" --threads "$threads" \
  --no-denoise --out "$out/lacrima.####.exr"
lacrima_seconds=$(echo "$(date +%s.%N) - $start" | bc)

echo "== Cycles"
start=$(date +%s.%N)
blender -b --factory-startup --python-exit-code 2 -P "$here/tools/peers/cycles_scene.py" -- \
  --shot "$shot" --glb "$out/geometry.$frame4.glb" --out "$out/cycles.exr" \
  "${cycles_spp_args[@]}" "${size_args[@]}" "${cycles_mnee[@]}" --threads "$threads" >"$out/cycles.log" 2>&1 \
  || { tail -20 "$out/cycles.log" >&2; exit 2; }
grep -E "^cycles_scene.py|Saved" "$out/cycles.log" || true
cycles_seconds=$(echo "$(date +%s.%N) - $start" | bc)

# The beauty alone on both sides (lacrima's EXR also holds its AOVs; Cycles' holds RGBA).
oiiotool "$out/lacrima.$frame4.exr" --ch R,G,B -o "$out/lacrima_rgb.exr"
oiiotool "$out/cycles.exr" --ch R,G,B -o "$out/cycles_rgb.exr"
preview() {  # linear ACEScg EXR -> display PNG, the same view as lacrima's previews
  oiiotool --colorconfig "$here/scenes/ocio/config.ocio" "$1" --iscolorspace ACEScg \
    --ociodisplay "sRGB - Display" "ACES 1.0 - SDR Video" -d uint8 -o "$2"
}
preview "$out/lacrima_rgb.exr" "$out/lacrima.png"
preview "$out/cycles_rgb.exr" "$out/cycles.png"

echo "== whole frame: Cycles (A) against lacrima (B)"
"$lacrima" diff "$out/cycles_rgb.exr" "$out/lacrima_rgb.exr" --flip-out "$out/flip.png" \
  --fail 1e9 >"$out/diff.txt" || true
cat "$out/diff.txt"
oiiotool "$out/lacrima.png" "$out/cycles.png" "$out/flip.png" --mosaic 3x1 -o "$out/side_by_side.png"

if [ -n "$region" ]; then
  read -r x y w h <<<"$region"
  echo "== region ${w}x${h} at ($x, $y)"
  for side in lacrima cycles; do
    oiiotool "$out/${side}_rgb.exr" --cut "${w}x${h}+${x}+${y}" -o "$out/${side}_region.exr"
    preview "$out/${side}_region.exr" "$out/${side}_region.png"
  done
  "$lacrima" diff "$out/cycles_region.exr" "$out/lacrima_region.exr" --flip-out "$out/flip_region.png" \
    --fail 1e9 >"$out/diff_region.txt" || true
  cat "$out/diff_region.txt"
  oiiotool "$out/lacrima_region.png" "$out/cycles_region.png" "$out/flip_region.png" --mosaic 3x1 \
    -o "$out/region_side_by_side.png"
fi
printf 'wall time: lacrima %.1f s, Cycles %.1f s (Blender start-up and scene set-up included)\n' \
  "$lacrima_seconds" "$cycles_seconds"
echo "pictures: $out/side_by_side.png (lacrima | Cycles | FLIP)${region:+, $out/region_side_by_side.png}"
