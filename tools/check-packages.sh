#!/usr/bin/env bash
# Fails when a configured CMake build uses a system file that a fresh Debian 12 machine would lack: one
# whose Debian package is neither in tools/setup.sh's packages=( ... ) nor in what those depend on.
# tools/test.sh runs it right after configure, so a package missing from setup.sh fails CI on the
# machines that happen to have it, instead of surfacing only on a new machine.
#
#   tools/check-packages.sh [--setup FILE] [BUILD_DIR ...]     default BUILD_DIR: build/default
#   tools/check-packages.sh --self-test [--setup FILE] [BUILD_DIR] [--remove PKG]
#       checks BUILD_DIR, then checks it again against a copy of setup.sh without PKG (default
#       libspirv-cross-c-shared-dev) and fails unless that run fails naming PKG
#   -v, --verbose: also list every file checked with its owners
#   FFX_DOF_SETUP=FILE                                       same as --setup FILE
#
# What it checks, per build directory's CMakeCache.txt:
#   - every PATH and FILEPATH entry (find_package's <Pkg>_DIR, find_path, find_library, find_program,
#     pkg_check_modules' pkgcfg_lib_*, the compilers and binutils), a ;-list split into paths; for a
#     <Pkg>_DIR folder, the <Pkg>Config.cmake / <pkg>-config.cmake file in it;
#   - every INTERNAL entry whose value is one existing file (CMAKE_COMMAND, Catch2's discovery script, ...);
#   - every pkg-config module a pkg_check_modules/pkg_search_module call found, as its .pc file
#     (pkg-config --variable=pcfiledir).
# Each path is looked up with dpkg-query -S as written, as realpath resolves it, and under the other
# merged-/usr spelling (/lib <-> /usr/lib, /bin <-> /usr/bin, /sbin <-> /usr/sbin), because dpkg records
# a file under the name its package ships. The owner of the path as written and the owner of the file it
# resolves to must both be provided. Paths no package owns (the source and build trees, files made by
# update-alternatives) are skipped; a folder owned by several packages (/usr/include) is provided when
# any of them is.
#
# Provided = the packages of setup.sh, plus every package Essential or of Priority required (what
# `mmdebstrap --variant=minbase` installs), plus apt, closed over Pre-Depends and Depends of the installed
# packages. The closure is computed from dpkg's status (not `apt-cache depends --installed`, which drops
# dependencies on virtual packages): for an alternative "a | b" the first installed one is taken (what
# apt installs), and a virtual package resolves to every installed package that Provides it.
#
# Exit status: 0 all provided (one line), 1 packages missing (each with the file that needs it), 2 usage.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
setup="${FFX_DOF_SETUP:-$root/tools/setup.sh}"
self_test=0
verbose=0
victim=libspirv-cross-c-shared-dev
builds=()
while [ $# -gt 0 ]; do
  case "$1" in
    --setup) setup="$2"; shift 2 ;;
    --self-test) self_test=1; shift ;;
    --remove) victim="$2"; shift 2 ;;
    -v|--verbose) verbose=1; shift ;;
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    -*) echo "check-packages: unknown option $1" >&2; exit 2 ;;
    *) builds+=("$1"); shift ;;
  esac
done
[ ${#builds[@]} -gt 0 ] || builds=("$root/build/default")
me="check-packages"

if [ "$self_test" = 1 ]; then
  # 1. The real setup.sh must pass; 2. without $victim it must fail and name $victim.
  "$0" --setup "$setup" "${builds[@]}" || { echo "$me self-test: the check fails with $setup itself" >&2; exit 1; }
  grep -qE "(^|[[:space:]])$victim([[:space:]]|$)" "$setup" ||
    { echo "$me self-test: $victim is not in $setup" >&2; exit 2; }
  copy="$(mktemp)"
  trap 'rm -f "$copy"' EXIT
  sed -E "/^packages=\(/,/^\)/s/(^|[[:space:]])$victim([[:space:]]|$)/\1\2/" "$setup" >"$copy"
  set +e
  out="$("$0" --setup "$copy" "${builds[@]}" 2>&1)"
  rc=$?
  set -e
  if [ $rc -eq 1 ] && grep -qE "^  $victim([[:space:]]|$)" <<<"$out"; then
    echo "$me self-test: without $victim in setup.sh the check fails and names it:"
    sed 's/^/    | /' <<<"$out"
    exit 0
  fi
  echo "$me self-test: without $victim in setup.sh the check did not fail naming it (exit $rc):" >&2
  sed 's/^/    | /' <<<"$out" >&2
  exit 1
fi

for tool in dpkg-query awk realpath; do
  command -v "$tool" >/dev/null || { echo "$me: needs $tool (Debian only)" >&2; exit 2; }
done
[ -f "$setup" ] || { echo "$me: no $setup" >&2; exit 2; }
mapfile -t listed < <(bash -c 'set -e; source <(sed -n "/^packages=(/,/^)/p" "$1"); printf "%s\n" "${packages[@]}"' _ "$setup")
[ ${#listed[@]} -gt 0 ] || { echo "$me: could not read packages=( ... ) in $setup" >&2; exit 2; }

# --- provided packages: setup.sh + the minbase set, closed over Pre-Depends/Depends ----------------------
provided="$(
  dpkg-query -W -f='${db:Status-Abbrev}\t${Package}\t${Essential}\t${Priority}\t${Provides}\t${Pre-Depends}, ${Depends}\n' |
  awk -F'\t' -v listed="${listed[*]}" '
    function bare(s) { gsub(/\(.*\)|\[.*\]|<.*>/, "", s); gsub(/[ \t]/, "", s); sub(/:.*/, "", s); return s }
    $1 ~ /^[ih]i/ {
      pkg = $2; inst[pkg] = 1; deps[pkg] = $6
      prov[pkg] = prov[pkg] " " pkg
      n = split($5, ps, ","); for (i = 1; i <= n; i++) { p = bare(ps[i]); if (p != "") prov[p] = prov[p] " " pkg }
      if ($3 == "yes" || $4 == "required" || pkg == "apt") queue[++tail] = pkg
    }
    END {
      n = split(listed, ls, " "); for (i = 1; i <= n; i++) queue[++tail] = ls[i]
      for (head = 1; head <= tail; head++) {
        pkg = queue[head]; if (pkg in seen) continue; seen[pkg] = 1
        if (!(pkg in inst)) continue
        ng = split(deps[pkg], groups, ",")
        for (g = 1; g <= ng; g++) {
          na = split(groups[g], alts, "|")
          for (a = 1; a <= na; a++) {
            name = bare(alts[a]); if (name == "" || !(name in prov)) continue
            m = split(prov[name], who, " "); for (k = 1; k <= m; k++) queue[++tail] = who[k]
            break
          }
        }
      }
      for (pkg in seen) if (pkg in inst) print pkg
    }'
)"
missing_listed=()
for p in "${listed[@]}"; do grep -qxF "$p" <<<"$provided" || missing_listed+=("$p"); done
if [ ${#missing_listed[@]} -gt 0 ]; then
  echo "$me: not installed here, run tools/setup.sh first: ${missing_listed[*]}" >&2
  exit 2
fi

# --- the system files each build found --------------------------------------------------------------------
# Lines "<path>\t<why>" where why is "<build>: <cache entry>".
alias_of() { # sets alias: the other merged-/usr spelling of $1, or ""   (no subshells: this runs ~200 times)
  case "$1" in
    /usr/lib/*|/usr/lib32/*|/usr/lib64/*|/usr/libx32/*|/usr/bin/*|/usr/sbin/*) alias="${1#/usr}" ;;
    /lib/*|/lib32/*|/lib64/*|/libx32/*|/bin/*|/sbin/*) alias="/usr$1" ;;
    *) alias="" ;;
  esac
}
config_file_in() { # $1 folder, $2 package name of <Pkg>_DIR
  local d="$1" n="$2" lower f
  lower="${n,,}"
  for f in "$d/${n}Config.cmake" "$d/${lower}-config.cmake" "$d"/*Config.cmake "$d"/*-config.cmake; do
    [ -f "$f" ] && { echo "$f"; return; }
  done
  echo "$d"
}

found=()   # "<path>\t<why>"
files=0
for build in "${builds[@]}"; do
  cache="$build/CMakeCache.txt"
  [ -f "$cache" ] || { echo "$me: no $cache (configure first)" >&2; exit 2; }
  src="$(sed -n 's/^CMAKE_HOME_DIRECTORY:INTERNAL=//p' "$cache")"
  bin="$(sed -n 's/^CMAKE_CACHEFILE_DIR:INTERNAL=//p' "$cache")"
  pkgconfig="$(sed -n 's/^PKG_CONFIG_EXECUTABLE:FILEPATH=//p' "$cache")"
  label="${build#$root/}"
  before=${#found[@]}
  while IFS= read -r line; do
    name="${line%%:*}"; rest="${line#*:}"; type="${rest%%=*}"; value="${rest#*=}"
    case "$name" in CMAKE_INSTALL_*|CMAKE_FIND_PACKAGE_REDIRECTS_DIR|*-ADVANCED) continue ;; esac
    IFS=';' read -r -a paths <<<"$value"
    for p in "${paths[@]}"; do
      [[ "$p" == /* ]] || continue
      [ -e "$p" ] || continue
      [ -n "$src" ] && [[ "$p" == "$src" || "$p" == "$src"/* ]] && continue
      [ -n "$bin" ] && [[ "$p" == "$bin" || "$p" == "$bin"/* ]] && continue
      if [ "$type" = INTERNAL ]; then [ -f "$p" ] || continue; fi
      if [ -d "$p" ] && [[ "$name" == *_DIR ]]; then p="$(config_file_in "$p" "${name%_DIR}")"; fi
      found+=("$p"$'\t'"$label: $name")
    done
  done < <(grep -E '^[A-Za-z0-9_.+-]+:(PATH|FILEPATH|INTERNAL)=/' "$cache")

  # pkg-config modules: __pkg_config_arguments_<PREFIX> holds the call's arguments; <PREFIX>_FOUND=1
  # (pkg_check_modules: every module) or <PREFIX>_MODULE_NAME (pkg_search_module: the one found).
  while IFS= read -r line; do
    prefix="${line#__pkg_config_arguments_}"; prefix="${prefix%%:INTERNAL=*}"; args="${line#*:INTERNAL=}"
    grep -qxF "${prefix}_FOUND:INTERNAL=1" "$cache" || continue
    module="$(sed -n "s/^${prefix}_MODULE_NAME:INTERNAL=//p" "$cache")"
    if [ -n "$module" ]; then modules=("$module"); else
      IFS=';' read -r -a modules <<<"$args"
    fi
    for m in "${modules[@]}"; do
      case "$m" in REQUIRED|QUIET|IMPORTED_TARGET|GLOBAL|NO_CMAKE_PATH|NO_CMAKE_ENVIRONMENT_PATH|"") continue ;; esac
      m="${m%%[<>=]*}"
      dir="$("${pkgconfig:-pkg-config}" --variable=pcfiledir "$m" 2>/dev/null || true)"
      if [ -z "$dir" ] || [ ! -f "$dir/$m.pc" ]; then
        echo "$me: pkg-config module $m ($label: $prefix) found at configure but not now" >&2; exit 2
      fi
      found+=("$dir/$m.pc"$'\t'"$label: pkg-config module $m ($prefix)")
    done
  done < <(grep -E '^__pkg_config_arguments_[A-Za-z0-9_]+:INTERNAL=' "$cache")
  [ ${#found[@]} -gt "$before" ] || { echo "$me: $cache names no system file; not a CMake cache this check understands" >&2; exit 2; }
done

# --- owners: one dpkg-query -S over every spelling of every path ---------------------------------------------
declare -A real=() owners=()
lookups=()
paths=()
for entry in "${found[@]}"; do paths+=("${entry%%$'\t'*}"); done
mapfile -t reals < <(realpath -e -- "${paths[@]}")
for i in "${!paths[@]}"; do
  p="${paths[$i]}"; r="${reals[$i]}"
  real[$p]="$r"
  alias_of "$p"; a1="$alias"; alias_of "$r"; a2="$alias"
  for q in "$p" "$a1" "$r" "$a2"; do
    [ -n "$q" ] && [[ "$q" != *[][*?\\]* ]] && lookups+=("$q")
  done
done
mapfile -t lookups < <(printf '%s\n' "${lookups[@]}" | sort -u)
while IFS= read -r line; do
  case "$line" in "diversion by "*) continue ;; esac
  [[ "$line" == *": /"* ]] || continue
  who="${line%%: /*}"; path="/${line#*: /}"
  who="${who//,/}"; set -- $who; who=""   # "a:amd64, b" -> "a b"
  for w in "$@"; do who+="${who:+ }${w%%:*}"; done
  owners[$path]="${owners[$path]:+${owners[$path]} }$who"
done < <(dpkg-query -S "${lookups[@]}" 2>/dev/null || true)

owners_of() { # sets own: the owners of $1 under either merged-/usr spelling
  alias_of "$1"
  own="${owners[$1]:-} ${alias:+${owners[$alias]:-}}"
}
declare -A is_prov=()
while IFS= read -r w; do [ -n "$w" ] && is_prov[$w]=1; done <<<"$provided"
is_provided() { # any of the words of $1 provided
  local w
  for w in $1; do [ -n "${is_prov[$w]:-}" ] && return 0; done
  return 1
}

short() { set -- $1; if [ $# -gt 3 ]; then echo "$1 $2 $3 ... ($# packages)"; else echo "$*"; fi; }
pkgs_used=""
declare -A need=()   # package -> "file (why)" lines
checked=0
unowned=()
for entry in "${found[@]}"; do
  p="${entry%%$'\t'*}"; why="${entry#*$'\t'}"
  r="${real[$p]}"
  owners_of "$p"; o1="$own"; owners_of "$r"; o2="$own"
  if [ -z "${o1// /}" ] && [ -z "${o2// /}" ]; then
    case "$p" in /usr/*|/lib*|/bin/*|/sbin/*|/opt/*|/etc/*) unowned+=("$p ($why)") ;; esac
    continue
  fi
  checked=$((checked + 1))
  [ "$verbose" = 1 ] && printf '  %s -> %s%s  [%s]\n' "$p" "$(short "$o1")" "$([ "$r" != "$p" ] && echo " | $r -> $(short "$o2")")" "$why"
  [ -f "$p" ] && pkgs_used+=" $o1 $o2"
  # The owner of the path as written (a -dev package for a .so link) or, when that one is provided or owns
  # nothing, the owner of the file it resolves to (the runtime library, an alternative's target).
  o="$o1"
  if [ -z "${o// /}" ] || is_provided "$o"; then o="$o2"; fi
  if [ -n "${o// /}" ] && ! is_provided "$o"; then
    set -- $o
    key="$*"; key="${key// / or }"
    file="$p"; [ "$r" != "$p" ] && file="$p -> $r"
    case "${need[$key]:-}" in *"$file ($why)"*) ;; *) need[$key]="${need[$key]:-}      $file ($why)"$'\n' ;; esac
  fi
done

if [ ${#need[@]} -gt 0 ]; then
  echo "$me: the build uses files from packages that ${setup#$root/} does not install (nor anything they depend on); a fresh Debian 12 machine lacks them:"
  while IFS= read -r key; do
    echo "  $key"
    printf '%s' "${need[$key]}"
  done < <(printf '%s\n' "${!need[@]}" | sort)
  echo "$me: add the package(s) above to packages=( ... ) in tools/setup.sh"
  exit 1
fi
if [ ${#unowned[@]} -gt 0 ]; then
  echo "$me: note: system files no Debian package owns (installed by hand? a fresh machine lacks them too):"
  printf '  %s\n' "${unowned[@]}"
fi
npkg="$(tr ' ' '\n' <<<"$pkgs_used" | sed '/^$/d' | sort -u | wc -l)"
echo "$me: the $checked system files CMake found ($(printf '%s ' "${builds[@]#$root/}" | sed 's/ $//')) come from $npkg packages, all installed by tools/setup.sh or its dependencies"
