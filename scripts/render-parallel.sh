#!/usr/bin/env bash
# Splits one long `physdbg render` into frame ranges and renders them through
# GNU parallel, on this machine or on several (--sshloginfile). The chunks
# write exactly the files one run would: each draws its slice --frames A:B of
# the same simulation (earlier frames are simulated, not drawn), and
# --of-run tells it the whole run's --frames, so the overlay's "frame i of N"
# reads as one run's. Add --no-timing for byte-identical frames (the measured
# step time is otherwise in the overlay) and set LP_NUM_THREADS=1.
#
# Usage: bash scripts/render-parallel.sh [-j JOBS] [--chunks K] [--sshloginfile FILE] \
#          SCENE -o DIR --frames N|A:B [other physdbg render options]
# -j: chunks rendered at once per machine (default: this machine's cores);
# --chunks: pieces the range is cut into (default: JOBS); --sshloginfile: the
# machines, as GNU parallel reads them; each must see physdbg, the scene file
# and DIR at the same paths (a shared folder). PHYSDBG names the binary
# (default build/cli/physdbg). Exit codes: physdbg render's; 2 for bad usage.
set -euo pipefail

usage() {
  echo "usage: bash scripts/render-parallel.sh [-j JOBS] [--chunks K] [--sshloginfile FILE] SCENE -o DIR" \
       "--frames N|A:B [physdbg render options]" >&2
  echo "render-parallel: $1" >&2
  exit 2
}

physdbg="${PHYSDBG:-$(dirname "$0")/../build/cli/physdbg}"
jobs="$(nproc)"
chunks=""
logins=()
render=()
output=""
frames=""
while (($#)); do
  case "$1" in
    -j | --jobs) (($# >= 2)) || usage "$1 needs a value"; jobs="$2"; shift 2 ;;
    --chunks) (($# >= 2)) || usage "$1 needs a value"; chunks="$2"; shift 2 ;;
    --sshloginfile) (($# >= 2)) || usage "$1 needs a value"; logins=(--sshloginfile "$2" --env LP_NUM_THREADS); shift 2 ;;
    -o | --output) (($# >= 2)) || usage "$1 needs a value"; output="$2"; shift 2 ;;
    --frames) (($# >= 2)) || usage "$1 needs a value"; frames="$2"; shift 2 ;;
    --video | --of-run) usage "$1 is not for a split render (encode the frames afterwards)" ;;
    *) render+=("$1"); shift ;;
  esac
done
chunks="${chunks:-$jobs}"
[[ "$jobs" =~ ^[1-9][0-9]{0,2}$ ]] || usage "-j: expected 1..999, got '$jobs'"
[[ "$chunks" =~ ^[1-9][0-9]{0,3}$ ]] || usage "--chunks: expected 1..9999, got '$chunks'"
[ -n "$output" ] || usage "-o DIR is required (every chunk writes there)"
[ -n "$frames" ] || usage "--frames N|A:B is required (the range to split)"
command -v parallel >/dev/null || usage "GNU parallel is not installed (apt-get install parallel, or bash scripts/setup.sh)"
[ -x "$physdbg" ] || usage "no physdbg at '$physdbg' (build it, or set PHYSDBG)"

if [[ "$frames" =~ ^([0-9]{1,7}):([0-9]{1,7})$ ]]; then
  first=$((10#${BASH_REMATCH[1]})); last=$((10#${BASH_REMATCH[2]})); whole=0
elif [[ "$frames" =~ ^[0-9]{1,7}$ ]]; then
  first=0; last=$((10#$frames)); whole=1
else
  usage "--frames: expected N or A:B, got '$frames'"
fi
((last > first)) || usage "--frames: '$frames' selects no frames"

# Paths every machine can follow: absolute.
mkdir -p "$output"
output="$(cd "$output" && pwd)"
physdbg="$(cd "$(dirname "$physdbg")" && pwd)/$(basename "$physdbg")"

# One run with --frames N owns the folder and removes every frame file first
# (physdbg render's rule, the names it writes); the slices remove only their own.
if ((whole)); then
  removed=0
  for file in "$output"/frame_*.png; do
    name="${file##*/}"
    if [[ "$name" =~ ^frame_([0-9]{5}|[1-9][0-9]{5,})\.png$ ]] && [ -f "$file" ]; then
      rm -- "$file"; removed=$((removed + 1))
    fi
  done
  ((removed == 0)) || echo "removed $removed frame files of an earlier run from $output"
fi

# Chunk i of K: frames first + i*count/K .. first + (i+1)*count/K - 1 (none empty when K <= count).
count=$((last - first))
((chunks <= count)) || chunks=$count
ranges=()
for ((i = 0; i < chunks; i++)); do
  ranges+=("$((first + i * count / chunks)):$((first + (i + 1) * count / chunks))")
done

# --quote: parallel passes every word to the chunk as it is, through no shell's reading.
exec parallel --will-cite --quote --halt now,fail=1 --jobs "$jobs" "${logins[@]}" \
  "$physdbg" render "${render[@]}" -o "$output" --frames {} --of-run "$frames" ::: "${ranges[@]}"
