#!/usr/bin/env bash
# The GPU figure on a machine with an NVIDIA GPU that has no package registry
# and no compiler: everything it runs is packed here and carried there.
#
#   bash scripts/gpu-check.sh pack [DIR] [--system-libs] [--binary FILE]
#       (here) copies build/cli/physdbg (no build) and the Debian libraries it
#       loads into DIR (default build/gpu-check): downloaded .deb files
#       (apt-get download) unpacked with dpkg -x into DIR/lib, or with
#       --system-libs this machine's own library files (no network). Writes
#       DIR/manifest.txt (packages, versions, the binary's sha256) and copies
#       this script to DIR/gpu-check.sh. Exit 2 when the binary is missing.
#   bash DIR/gpu-check.sh run [--timeout S] [--quick] [--results DIR]
#       (there) runs physdbg gpu-info and physdbg bench gpu --json on the EGL
#       backend with DIR/lib first on LD_LIBRARY_PATH, within S seconds in all
#       (default 300), saves the outputs in DIR/results/TIME/ and ends with one
#       summary line, "gpu-check: renderer ... | drop spheres N: gpu .. cpu ..
#       ms/step, ratio .. | ...", or "gpu-check: FAILED ..." saying why (exit 1).
#   bash scripts/gpu-check.sh selftest [--binary FILE]
#       (the CTest test) packs with --system-libs, copies the folder, runs it
#       with --quick and checks the summary line, then checks that a run without
#       an EGL driver fails with a FAILED summary. Exit 77 (skip) without dpkg.
#
# The packed folder expects an x86_64 Linux with glibc 2.36 or newer (Debian 12
# or newer; Ubuntu 22.04 has 2.35 and is too old: Debian 12's libLLVM-15, which
# libOSMesa links, needs 2.36) and the NVIDIA driver with its EGL library.
set -euo pipefail

self="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/$(basename "${BASH_SOURCE[0]}")"
here="$(dirname "$self")"

die() {  # die CODE MESSAGE
  echo "gpu-check: $2" >&2
  exit "$1"
}

usage() {
  sed -n '2,/^set -euo/p' "$self" | sed -e '$d' -e 's/^# \{0,1\}//' >&2
  [ -n "${1:-}" ] && echo "gpu-check: $1" >&2
  exit 2
}

# ---------------------------------------------------------------- pack (here)

# Packages never shipped: glibc (libc6: libc, libm, libpthread, libdl, the
# dynamic loader) must be the GPU machine's own, since its loader and the
# NVIDIA driver's libraries are loaded into the same process and one process
# cannot mix two glibcs; hence the glibc 2.36 floor above. libstdc++6 and
# libgcc-s1 are left to the machine too: every system with glibc 2.36 or newer
# has a GCC 12 or newer libstdc++, which holds every GLIBCXX version the binary
# needs (3.4.30), and shipping ours would shadow a newer one that the driver's
# libraries may need. Everything else the binary loads (Bullet, libccd, oneTBB,
# OSMesa and the LLVM it links, GLEW, libglvnd, X11 client libraries, zlib,
# ICU, ...) is shipped: a bare NVIDIA machine may lack any of them, or have
# another soname version.
skip_packages=(libc6 libstdc++6 libgcc-s1)
# EGL on the NVIDIA driver goes through libglvnd: its libEGL (libegl1) and
# dispatch library (libglvnd0) are shipped even if ldd stopped naming them.
# Mesa's EGL vendor (libegl-mesa0) is not: on the GPU machine glvnd must pick
# the driver's vendor file.
extra_packages=(libegl1 libglvnd0)

is_skipped() {
  local p
  for p in "${skip_packages[@]}"; do [ "$1" = "$p" ] && return 0; done
  return 1
}

# owner_of FILE: the installed package (with its architecture) that owns FILE;
# tries the path ldd gave, its real path, and both with and without /usr
# (Debian 12 has merged /usr but dpkg records each file under one of them).
owner_of() {
  local file="$1" real candidate line
  real="$(readlink -f -- "$file")"
  for candidate in "$file" "$real" "${file#/usr}" "/usr$file" "${real#/usr}" "/usr$real"; do
    line="$(dpkg -S "$candidate" 2>/dev/null | grep -v '^diversion by' | head -n 1)" || true
    if [ -n "$line" ]; then
      line="${line%%: *}"
      echo "${line%%,*}"
      return 0
    fi
  done
  return 1
}

# library_dirs DIR: the folders under DIR holding shared libraries, one a line.
library_dirs() {
  find "$1" \( -type f -o -type l \) -name 'lib*.so*' -exec dirname {} \; | sort -u
}

library_path_for() {  # library_path_for DIR: those folders joined with ':'
  library_dirs "$1" | paste -s -d ':' -
}

pack() {
  local dir="" mode=download binary=""
  while (($#)); do
    case "$1" in
      --system-libs | --no-download) mode=system-libs; shift ;;
      --binary) (($# >= 2)) || usage "$1 needs a value"; binary="$2"; shift 2 ;;
      -h | --help) usage ;;
      -*) usage "pack: unknown option '$1'" ;;
      *) [ -z "$dir" ] || usage "pack: one DIR only"; dir="$1"; shift ;;
    esac
  done
  [ -n "$binary" ] || binary="$here/../build/cli/physdbg"
  [ -n "$dir" ] || dir="$here/../build/gpu-check"
  case "$dir" in *:*) die 2 "pack: DIR must not contain ':' (it goes into LD_LIBRARY_PATH): $dir" ;; esac
  [ -f "$binary" ] || die 2 "pack: no physdbg binary at $binary (build the Release binary first: bash scripts/build.sh)"
  binary="$(cd "$(dirname "$binary")" && pwd)/$(basename "$binary")"
  local tool
  for tool in ldd dpkg dpkg-query sha256sum; do
    command -v "$tool" >/dev/null || die 2 "pack: needs $tool (run pack on the Debian 12 machine that built physdbg)"
  done
  [ "$mode" = system-libs ] || command -v apt-get >/dev/null || die 2 "pack: needs apt-get (or use --system-libs)"

  local tmp
  tmp="$(mktemp -d "${TMPDIR:-/tmp}/gpu-check-pack.XXXXXX")"
  # shellcheck disable=SC2064  # expand now: $tmp is local
  trap "rm -rf -- '$tmp'" EXIT
  # Copy the binary once, first: the build folder may be rebuilt while we pack.
  cp -- "$binary" "$tmp/physdbg"
  chmod 755 "$tmp/physdbg"
  "$tmp/physdbg" --help >/dev/null 2>&1 || die 2 "pack: $binary does not run here (being rebuilt?)"

  if [ -e "$dir" ]; then
    [ -d "$dir" ] || die 2 "pack: $dir exists and is not a folder"
    if [ -f "$dir/manifest.txt" ] && grep -q '^format gpu-check 1$' "$dir/manifest.txt"; then
      rm -rf -- "${dir:?}/lib" "$dir/physdbg" "$dir/manifest.txt" "$dir/gpu-check.sh"  # an earlier pack; results stay
    elif [ -n "$(ls -A -- "$dir")" ]; then
      die 2 "pack: $dir is not empty and holds no gpu-check manifest; name a new folder"
    fi
  fi
  mkdir -p -- "$dir/lib"
  dir="$(cd "$dir" && pwd)"

  # Which packages: ldd's transitive list, each library resolved to its owner.
  local ldd_out soname arrow path rest pkg base
  ldd_out="$(ldd "$tmp/physdbg")" || die 2 "pack: ldd failed on $binary"
  local -A owners=()      # package:arch -> 1
  local -a order=() files=()
  while read -r soname arrow path rest; do
    [ "$arrow" = "=>" ] || continue  # linux-vdso and the dynamic loader have no "=>"
    [ "$path" != not ] || die 2 "pack: $soname is not found on this machine (ldd $binary)"
    pkg="$(owner_of "$path")" || die 2 "pack: no installed package owns $path ($soname)"
    base="${pkg%%:*}"
    is_skipped "$base" && continue
    files+=("$soname" "$path")
    if [ -z "${owners[$pkg]:-}" ]; then owners[$pkg]=1; order+=("$pkg"); fi
  done <<<"$ldd_out"
  local arch
  arch="$(dpkg --print-architecture)"
  for base in "${extra_packages[@]}"; do
    if [ -z "${owners[$base:$arch]:-}" ] && [ -z "${owners[$base]:-}" ]; then owners[$base:$arch]=1; order+=("$base:$arch"); fi
  done

  local -a manifest=() specs=()
  local version
  for pkg in "${order[@]}"; do
    version="$(dpkg-query -W -f '${Version}' "$pkg")" || die 2 "pack: $pkg is not installed"
    specs+=("$pkg=$version")
  done

  local total=0 size deb name
  if [ "$mode" = download ]; then
    mkdir "$tmp/debs"
    # apt drops to the _apt user to download; let it write there.
    if [ "$(id -u)" = 0 ] && id _apt >/dev/null 2>&1; then chown _apt "$tmp/debs"; fi
    echo "gpu-check: downloading ${#specs[@]} packages (apt-get download)" >&2
    if ! (cd "$tmp/debs" && apt-get download "${specs[@]}") >"$tmp/apt.log" 2>&1; then
      # One at a time, and the archive's version where the installed one is gone.
      local spec
      for spec in "${specs[@]}"; do
        [ -n "$(find "$tmp/debs" -name "${spec%%[:=]*}_*.deb" -print -quit)" ] && continue
        if ! (cd "$tmp/debs" && apt-get download "$spec") >>"$tmp/apt.log" 2>&1; then
          echo "gpu-check: $spec is not in the archive; taking its candidate version" >&2
          (cd "$tmp/debs" && apt-get download "${spec%%=*}") >>"$tmp/apt.log" 2>&1 ||
            { cat "$tmp/apt.log" >&2; die 2 "pack: apt-get download ${spec%%=*} failed"; }
        fi
      done
    fi
    local host_version
    for deb in "$tmp"/debs/*.deb; do
      dpkg -x "$deb" "$dir/lib"
      name="$(dpkg-deb -f "$deb" Package)"
      version="$(dpkg-deb -f "$deb" Version)"
      size="$(stat -c %s "$deb")"
      total=$((total + size))
      manifest+=("package $name $version $(dpkg-deb -f "$deb" Architecture) $size")
      host_version="$(dpkg-query -W -f '${Version}' "$name:$(dpkg-deb -f "$deb" Architecture)")"
      [ "$host_version" = "$version" ] || manifest+=("host_has $name $host_version (installed here; the archive no longer has it)")
    done
  else
    # The host's own files, resolved as ldd resolved them, under their soname.
    local i target
    for ((i = 0; i < ${#files[@]}; i += 2)); do
      target="$dir/lib$(dirname "$(readlink -f -- "${files[i + 1]}")")"
      mkdir -p -- "$target"
      cp -L -- "${files[i + 1]}" "$target/${files[i]}"
      size="$(stat -c %s "$target/${files[i]}")"
      total=$((total + size))
    done
    for ((i = 0; i < ${#specs[@]}; i++)); do
      manifest+=("package ${order[i]%%:*} ${specs[i]##*=} $arch host-files")
    done
  fi

  # Every library the binary loads must now come from DIR/lib (or be skipped).
  local libpath resolved missing=""
  libpath="$(library_path_for "$dir/lib")"
  resolved="$(LD_LIBRARY_PATH="$libpath" ldd "$tmp/physdbg")"
  for ((i = 0; i < ${#files[@]}; i += 2)); do
    grep -qF -- "${files[i]} => $dir/lib/" <<<"$resolved" || missing+=" ${files[i]}"
  done
  [ -z "$missing" ] || die 2 "pack: not resolved inside $dir/lib:$missing"

  # The glibc the package needs: the newest GLIBC_ symbol version the binary
  # and the shipped libraries ask for (objdump), else this machine's (an upper bound).
  local glibc host_glibc
  host_glibc="$(getconf GNU_LIBC_VERSION | awk '{print $2}')"
  glibc=""
  if command -v objdump >/dev/null; then
    glibc="$( { objdump -T "$tmp/physdbg"
                find "$dir/lib" -type f -name 'lib*.so*' -exec objdump -T {} \; ; } 2>/dev/null |
              grep -oE 'GLIBC_[0-9]+\.[0-9]+(\.[0-9]+)?' | sed 's/^GLIBC_//' | sort -V | tail -n 1)"
  fi
  [ -n "$glibc" ] || glibc="$host_glibc"

  mv -- "$tmp/physdbg" "$dir/physdbg"
  cp -- "$self" "$dir/gpu-check.sh"
  local commit=""
  if command -v git >/dev/null && git -C "$here/.." rev-parse HEAD >/dev/null 2>&1; then
    commit="$(git -C "$here/.." rev-parse HEAD)"
    [ -z "$(git -C "$here/.." status --porcelain --untracked-files=no 2>/dev/null)" ] || commit+=" (uncommitted changes)"
  fi
  {
    echo "# gpu-check manifest: bash gpu-check.sh run reads it"
    echo "format gpu-check 1"
    echo "packed $(date -u +%Y-%m-%dT%H:%M:%SZ) mode $mode"
    echo "binary physdbg sha256 $(sha256sum "$dir/physdbg" | awk '{print $1}') from $binary"
    [ -z "$commit" ] || echo "source_commit $commit"
    echo "arch $(uname -m)"
    echo "needs_glibc $glibc (packed on glibc $host_glibc)"
    for base in "${skip_packages[@]}"; do echo "not_shipped $base (the GPU machine's own)"; done
    printf '%s\n' "${manifest[@]}"
    echo "total_bytes $total (${#specs[@]} packages)"
  } >"$dir/manifest.txt"
  echo "gpu-check: packed $dir: physdbg, ${#specs[@]} packages ($mode, $((total / 1048576)) MiB), needs glibc $glibc" \
       "and $(uname -m); there: bash $(basename "$dir")/gpu-check.sh run"
}

# ----------------------------------------------------------- run (GPU machine)

message() {  # message FILE head|tail: its first or last line that is not empty, or nothing
  grep -v '^$' "$1" 2>/dev/null | "$2" -n 1 || true
}

summary_fail() {  # summary_fail RESULTS REASON: the FAILED summary line, exit 1
  local line="gpu-check: FAILED: $2${1:+ | results $1}"
  [ -z "$1" ] || echo "$line" >"$1/summary.txt"
  echo "$line"
  exit 1
}

# The NVIDIA EGL vendor: glvnd's libEGL reads /etc/glvnd/egl_vendor.d and
# /usr/share/glvnd/egl_vendor.d. When the driver's file is not there, look in
# the other usual places (containers, the GPU operator's driver root, a
# /usr/local install), else write one for libEGL_nvidia.so.0 if the driver's
# library is found, and point __EGL_VENDOR_LIBRARY_FILENAMES at it.
choose_egl_vendor() {  # choose_egl_vendor RESULTS: sets vendor to what it used
  local results="$1" d f lib
  local -a dirs
  if [ -n "${__EGL_VENDOR_LIBRARY_FILENAMES:-}" ]; then
    vendor="__EGL_VENDOR_LIBRARY_FILENAMES=$__EGL_VENDOR_LIBRARY_FILENAMES (set by the caller)"
    return
  fi
  for d in /etc/glvnd/egl_vendor.d /usr/share/glvnd/egl_vendor.d; do
    for f in "$d"/*nvidia*.json; do
      [ -f "$f" ] && { vendor="$f (in glvnd's default folders)"; return; }
    done
  done
  for d in /usr/local/share/glvnd/egl_vendor.d /usr/local/etc/glvnd/egl_vendor.d \
           /usr/local/nvidia/share/glvnd/egl_vendor.d /run/nvidia/driver/usr/share/glvnd/egl_vendor.d \
           /run/nvidia/driver/etc/glvnd/egl_vendor.d /usr/lib/x86_64-linux-gnu/nvidia/egl_vendor.d \
           /usr/lib64/nvidia/egl_vendor.d /opt/nvidia/share/glvnd/egl_vendor.d; do
    for f in "$d"/*nvidia*.json; do
      if [ -f "$f" ]; then
        export __EGL_VENDOR_LIBRARY_FILENAMES="$f"
        vendor="__EGL_VENDOR_LIBRARY_FILENAMES=$f"
        return
      fi
    done
  done
  lib=""
  IFS=: read -r -a dirs <<<"${LD_LIBRARY_PATH:-}"
  for d in "${dirs[@]}" /usr/lib/x86_64-linux-gnu /usr/lib64 /usr/lib /usr/local/nvidia/lib64 \
           /usr/local/nvidia/lib /run/nvidia/driver/usr/lib/x86_64-linux-gnu /run/nvidia/driver/usr/lib64; do
    [ -e "$d/libEGL_nvidia.so.0" ] && { lib="$d/libEGL_nvidia.so.0"; break; }
  done
  if [ -z "$lib" ] && [ -x /sbin/ldconfig ]; then
    lib="$(/sbin/ldconfig -p 2>/dev/null | awk '$1 == "libEGL_nvidia.so.0" {print $NF; exit}')"
  fi
  if [ -n "$lib" ]; then
    printf '{\n  "file_format_version": "1.0.0",\n  "ICD": { "library_path": "%s" }\n}\n' "$lib" >"$results/10_nvidia.json"
    export __EGL_VENDOR_LIBRARY_FILENAMES="$results/10_nvidia.json"
    vendor="__EGL_VENDOR_LIBRARY_FILENAMES=$results/10_nvidia.json (written for $lib: no NVIDIA vendor file found)"
    return
  fi
  vendor="no NVIDIA EGL vendor file or libEGL_nvidia.so.0 found; glvnd takes whatever vendor this machine has"
}

# summarize GPU_INFO BENCH_JSONL: "renderer "..." | cpu T threads | drop spheres N: gpu A cpu B ms/step, ratio R | ..."
# bench prints one flat JSON object a line (keys sorted, no nesting); plain
# awk reads the fields, since the GPU machine may have neither jq nor python.
summarize() {
  local renderer
  renderer="$(sed -n 's/^renderer  *//p' "$1" | head -n 1 | tr '"' "'")"
  awk -v renderer="$renderer" '
    function str(key,   m) {
      if (!match($0, "\"" key "\":\"[^\"]*\"")) return ""
      m = substr($0, RSTART, RLENGTH); sub("^\"" key "\":\"", "", m); sub("\"$", "", m); return m
    }
    function num(key,   m) {
      if (!match($0, "\"" key "\":-?[0-9][0-9.eE+-]*")) return ""
      m = substr($0, RSTART, RLENGTH); sub("^\"" key "\":", "", m); return m
    }
    /^\{/ {
      name = str("name"); sub("^gpu/", "", name); gsub("/", " ", name)
      if (name == "" || num("ours_ms") == "" || num("peer_ms") == "") next
      if (num("threads") != "") threads = num("threads")
      cases = cases sprintf(" | %s %s: gpu %.3g cpu %.3g ms/step, ratio %.3g", name, num("n"),
                            num("ours_ms") + 0, num("peer_ms") + 0, num("ratio") + 0)
      count++
    }
    END {
      printf "renderer \"%s\"", renderer
      if (threads != "") printf " | cpu %s threads", threads
      printf "%s\n", cases
      exit count == 0
    }' "$2"
}

run() {
  local limit=300 quick=() results=""
  while (($#)); do
    case "$1" in
      --timeout) (($# >= 2)) || usage "$1 needs a value"; limit="$2"; shift 2 ;;
      --quick) quick=(--quick); shift ;;
      --results) (($# >= 2)) || usage "$1 needs a value"; results="$2"; shift 2 ;;
      -h | --help) usage ;;
      *) usage "run: unknown argument '$1'" ;;
    esac
  done
  if ! [[ "$limit" =~ ^[0-9]+$ ]] || ((limit < 10 || limit > 3600)); then
    usage "run: --timeout takes 10 to 3600 seconds"
  fi
  local start
  start="$(date +%s)"
  local bin="$here/physdbg" manifest_file="$here/manifest.txt"
  if [ ! -f "$bin" ] || [ ! -f "$manifest_file" ] || [ ! -d "$here/lib" ]; then
    summary_fail "" "$here is not a packed folder (no physdbg, manifest.txt or lib/): run 'gpu-check.sh pack DIR' on the build machine and copy DIR here"
  fi
  if [ -z "$results" ]; then  # in the packed folder, else (read-only) in /tmp
    results="$(mkdir -p -- "$here/results" 2>/dev/null &&
               mktemp -d "$here/results/$(date +%Y%m%d-%H%M%S)-XXXX" 2>/dev/null)" ||
      results="$(mktemp -d "${TMPDIR:-/tmp}/gpu-check-results.XXXXXX")"
  fi
  mkdir -p -- "$results" || die 2 "run: cannot create $results"
  results="$(cd "$results" && pwd)"

  command -v timeout >/dev/null || summary_fail "$results" "needs coreutils' timeout"

  local want_arch need_glibc have_glibc want_sha have_sha
  want_arch="$(sed -n 's/^arch //p' "$manifest_file")"
  [ "$(uname -m)" = "$want_arch" ] || summary_fail "$results" "this machine is $(uname -m), the package is for $want_arch"
  need_glibc="$(sed -n 's/^needs_glibc \([0-9.]*\).*/\1/p' "$manifest_file")"
  have_glibc="$(getconf GNU_LIBC_VERSION 2>/dev/null | awk '{print $2}')" || true
  want_sha="$(sed -n 's/^binary physdbg sha256 \([0-9a-f]*\).*/\1/p' "$manifest_file")"
  if command -v sha256sum >/dev/null; then
    have_sha="$(sha256sum "$bin" | awk '{print $1}')"
    [ "$have_sha" = "$want_sha" ] || summary_fail "$results" "physdbg's sha256 is not the manifest's (a damaged copy): copy the folder again"
  fi

  local libpath
  libpath="$(library_path_for "$here/lib")"
  export LD_LIBRARY_PATH="$libpath${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
  chmod u+x "$bin" 2>/dev/null || true
  {
    echo "date $(date -u +%Y-%m-%dT%H:%M:%SZ)"
    echo "host $(uname -srm)"
    echo "glibc ${have_glibc:-unknown} (package needs $need_glibc)"
    echo "LD_LIBRARY_PATH $LD_LIBRARY_PATH"
    grep -E '^(packed|binary|source_commit) ' "$manifest_file"
    if command -v nvidia-smi >/dev/null; then
      timeout 30 nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader 2>&1 | sed 's/^/nvidia-smi /'
    else
      echo "nvidia-smi not found"
    fi
  } >"$results/host.txt" 2>&1 || true
  local vendor=""
  choose_egl_vendor "$results"
  echo "EGL vendor $vendor" >>"$results/host.txt"
  echo "gpu-check: EGL vendor: $vendor" >&2
  echo "gpu-check: results in $results" >&2

  # Does it start at all? The loader's complaint (a missing GLIBC_2.36...) is the reason.
  local rc=0
  "$bin" --help >/dev/null 2>"$results/start.stderr" || rc=$?
  if ((rc != 0)); then
    local why
    why="$(message "$results/start.stderr" head)"
    if [ -n "$have_glibc" ] && [ "$(printf '%s\n' "$need_glibc" "$have_glibc" | sort -V | head -n 1)" != "$need_glibc" ]; then
      why+=" (this machine has glibc $have_glibc, the package needs $need_glibc: Debian 12 or newer)"
    fi
    summary_fail "$results" "physdbg does not start here: ${why:-exit status $rc}"
  fi

  local left
  left=$((limit - ($(date +%s) - start)))
  echo "gpu-check: physdbg gpu-info --backend egl" >&2
  timeout -k 5 "$((left < 60 ? left : 60))" "$bin" gpu-info --backend egl >"$results/gpu-info.txt" 2>"$results/gpu-info.stderr" || rc=$?
  cat "$results/gpu-info.txt" >&2
  if ((rc != 0)); then
    local why
    why="$(message "$results/gpu-info.stderr" tail)"
    ((rc != 124 && rc != 137)) || why="no answer in $((left < 60 ? left : 60)) s"
    summary_fail "$results" "gpu-info exited $rc: ${why:-no message} (EGL vendor: $vendor)"
  fi

  left=$((limit - ($(date +%s) - start)))
  ((left >= 5)) || summary_fail "$results" "no time left for the benchmark within --timeout $limit"
  echo "gpu-check: physdbg bench gpu --backend egl --json ${quick[*]} (at most ${left} s)" >&2
  rc=0
  timeout -k 10 "$left" "$bin" bench gpu --backend egl --json "${quick[@]}" >"$results/bench.jsonl" 2>"$results/bench.stderr" || rc=$?
  cat "$results/bench.jsonl" >&2

  local line
  if ! line="$(summarize "$results/gpu-info.txt" "$results/bench.jsonl")"; then
    local why
    why="$(message "$results/bench.stderr" tail)"
    ((rc != 124 && rc != 137)) || why="stopped by --timeout $limit"
    summary_fail "$results" "bench gpu gave no result (exit $rc: ${why:-no message}) | $line"
  fi
  if ((rc != 0)); then
    local why
    why="$(message "$results/bench.stderr" tail)"
    ((rc != 124 && rc != 137)) || why="stopped by --timeout $limit"
    summary_fail "$results" "bench gpu exited $rc after these cases: ${why:-no message} | $line"
  fi
  line="gpu-check: $line | results $results"
  echo "$line" >"$results/summary.txt"
  echo "$line"
}

# ----------------------------------------------------- selftest (CTest, here)

selftest() {
  local binary="$here/../build/cli/physdbg"
  while (($#)); do
    case "$1" in
      --binary) (($# >= 2)) || usage "$1 needs a value"; binary="$2"; shift 2 ;;
      *) usage "selftest: unknown argument '$1'" ;;
    esac
  done
  command -v dpkg >/dev/null || { echo "gpu-check selftest: skipped (no dpkg: pack needs a Debian system)"; exit 77; }
  [ -x "$binary" ] || { echo "gpu-check selftest: FAIL: no physdbg binary at $binary" >&2; exit 1; }
  local work
  work="$(mktemp -d "${TMPDIR:-/tmp}/gpu-check-selftest.XXXXXX")"
  fail() {  # keeps the outputs, not the 190 MB of libraries
    [ ! -f "$work/run.stderr" ] || cat "$work/run.stderr" >&2
    rm -rf -- "${work:?}/packed" "$work/copy/lib" "$work/copy/physdbg"
    echo "gpu-check selftest: FAIL: $1 (outputs kept in $work)" >&2
    exit 1
  }

  # What the renderer should be: the binary's own answer on this machine.
  local renderer
  renderer="$("$binary" gpu-info --backend egl | sed -n 's/^renderer  *//p' | tr '"' "'")" ||
    fail "physdbg gpu-info --backend egl fails on this machine"

  bash "$self" pack "$work/packed" --system-libs --binary "$binary" || fail "pack --system-libs failed"
  cp -R "$work/packed" "$work/copy"
  rm -rf -- "${work:?}/packed"
  [ -f "$work/copy/gpu-check.sh" ] || fail "the packed folder has no gpu-check.sh"
  local libpath loaded
  libpath="$(library_path_for "$work/copy/lib")"
  # Read whole before matching: grep -q stops at the first match, and under
  # pipefail the ldd it cut off would fail the pipeline now and then.
  loaded="$(LD_LIBRARY_PATH="$libpath" ldd "$work/copy/physdbg")" || fail "ldd cannot read the copy's physdbg"
  grep -qF "libEGL.so.1 => $work/copy/lib/" <<<"$loaded" ||
    fail "the copy's physdbg does not load libEGL.so.1 from the copy's lib/"

  local out rc=0 summary
  out="$(cd "$work/copy" && bash gpu-check.sh run --quick 2>"$work/run.stderr")" || rc=$?
  summary="$(tail -n 1 <<<"$out")"
  echo "$summary"
  ((rc == 0)) || fail "run --quick exited $rc: $summary"
  [[ "$summary" == "gpu-check: renderer \"$renderer\" | "* ]] || fail "the summary does not start with renderer \"$renderer\""
  local number='[0-9][0-9.e+-]*'
  [[ "$summary" =~ \|\ drop\ spheres\ 64:\ gpu\ $number\ cpu\ $number\ ms/step,\ ratio\ $number\ \|\ drop\ boxes\ 64:\ gpu\ $number\ cpu\ $number\ ms/step,\ ratio\ $number\ \|\ results\ (.*)$ ]] ||
    fail "the summary lacks the two quick cases with their times and ratios"
  local results="${BASH_REMATCH[1]}"
  [[ "$results" == "$work/copy/results/"* ]] || fail "results are not in the copied folder: $results"
  [ "$(grep -c '^{' "$results/bench.jsonl")" = 2 ] || fail "$results/bench.jsonl does not hold 2 records"

  # Without an EGL driver gpu-info fails: the run must say so and exit non-zero.
  rc=0
  out="$(cd / && __EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent/gpu-check.json \
           bash "$work/copy/gpu-check.sh" run --quick 2>>"$work/run.stderr")" || rc=$?
  summary="$(tail -n 1 <<<"$out")"
  echo "$summary"
  ((rc != 0)) || fail "run without an EGL driver exited 0"
  [[ "$summary" == "gpu-check: FAILED: gpu-info exited "* ]] || fail "run without an EGL driver does not end with a FAILED gpu-info summary"
  rm -rf -- "${work:?}"
  echo "gpu-check selftest: PASS"
}

case "${1:-}" in
  pack) shift; pack "$@" ;;
  run) shift; run "$@" ;;
  selftest) shift; selftest "$@" ;;
  -h | --help | help) usage ;;
  *) usage "name a step: pack, run or selftest" ;;
esac
