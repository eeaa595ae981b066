#!/usr/bin/env bash
# Clean-room proof of the README's "Two commands": builds a minimal Debian 12 root from Debian's archive
# (mmdebstrap --variant=minbase, plus git and ca-certificates: "a fresh Debian 12 machine with a clone"),
# clones this repository's HEAD into it, and runs inside it (chroot, in a private mount namespace)
#     bash tools/demo.sh     then     bash tools/test.sh
# timing each, as root with no sudo and no XDG_RUNTIME_DIR (the scripts must cope). Prints the two cold
# times: new machine -> first picture, and -> a green test run. Not run by CI (it downloads ~1 GB and
# takes tens of minutes); run it after changing tools/setup.sh or the build's dependencies.
#
#   sudo tools/fresh-machine-check.sh [--keep] [DIR]
#     DIR      where to build the root (default: a new /var/tmp/ffx-dof-fresh.XXXXXX); must not exist or be empty
#     --keep   leave the root in place afterwards (default: delete it)
#   FRESH_SOURCES="deb URL SUITE COMPONENTS|..."   apt sources for the root (default: this machine's
#                                                 bookworm sources from /etc/apt, so the same mirror)
#
# Needs root (mmdebstrap in root mode, mount, chroot) and Debian; installs mmdebstrap on this machine with
# apt-get if it is missing (it is not in tools/setup.sh: only this script uses it).
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
keep=0
dir=""
for arg in "$@"; do
  case "$arg" in
    --keep) keep=1 ;;
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    -*) echo "fresh-machine-check: unknown option $arg" >&2; exit 2 ;;
    *) dir="$arg" ;;
  esac
done
me="fresh-machine-check"
[ "$(id -u)" -eq 0 ] || { echo "$me: run as root (mmdebstrap, mount, chroot)" >&2; exit 2; }

if ! command -v mmdebstrap >/dev/null; then
  echo "$me: installing mmdebstrap on this machine (apt-get)"
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends mmdebstrap >/dev/null
fi

# This machine's bookworm sources (deb822 .sources and one-line .list), so the root uses the same mirror.
sources=()
if [ -n "${FRESH_SOURCES:-}" ]; then
  IFS='|' read -r -a sources <<<"$FRESH_SOURCES"
else
  for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
    [ -f "$f" ] || continue
    while IFS= read -r line; do sources+=("$line"); done < <(
      sed -nE 's/^[[:space:]]*deb[[:space:]]+(\[[^]]*\][[:space:]]+)?([^[:space:]]+[[:space:]]+bookworm[^[:space:]]*[[:space:]].*)$/deb \2/p' "$f")
  done
  for f in /etc/apt/sources.list.d/*.sources; do
    [ -f "$f" ] || continue
    while IFS= read -r line; do sources+=("$line"); done < <(awk '
      function flush() {
        if (types ~ /(^| )deb( |$)/ && enabled != "no")
          for (i = 1; i <= nu; i++) for (j = 1; j <= ns; j++) if (s[j] ~ /^bookworm/) print "deb " u[i] " " s[j] " " comps
        types = ""; nu = 0; ns = 0; comps = ""; enabled = ""
      }
      /^[[:space:]]*$/ { flush(); next }
      /^#/ { next }
      tolower($1) == "types:" { types = ""; for (i = 2; i <= NF; i++) types = types " " $i; types = types " " }
      tolower($1) == "uris:" { for (i = 2; i <= NF; i++) u[++nu] = $i }
      tolower($1) == "suites:" { for (i = 2; i <= NF; i++) s[++ns] = $i }
      tolower($1) == "components:" { comps = ""; for (i = 2; i <= NF; i++) comps = comps (i > 2 ? " " : "") $i }
      tolower($1) == "enabled:" { enabled = tolower($2) }
      END { flush() }' "$f")
  done
fi
[ ${#sources[@]} -gt 0 ] || { echo "$me: found no bookworm source in /etc/apt; set FRESH_SOURCES" >&2; exit 2; }

if [ -z "$dir" ]; then dir="$(mktemp -d /var/tmp/ffx-dof-fresh.XXXXXX)"; fi
mkdir -p "$dir"
dir="$(realpath "$dir")"
[ -z "$(ls -A "$dir")" ] || { echo "$me: $dir is not empty" >&2; exit 2; }
logs="$dir.logs"
mkdir -p "$logs"

cleanup() {
  if [ "$keep" = 1 ]; then echo "$me: root kept in $dir (logs in $logs)"; return; fi
  # The mounts lived in a private mount namespace that is gone; never delete through a live mount.
  if grep -qF " $dir/" /proc/mounts || grep -qF " $dir " /proc/mounts; then
    echo "$me: something is still mounted under $dir; not deleting it" >&2; return
  fi
  rm -rf --one-file-system "$dir"
  echo "$me: root deleted (logs in $logs)"
}
trap cleanup EXIT

now() { date +%s.%N; }
mmss() { awk -v s="$1" 'BEGIN { printf "%d min %02d s", int(s / 60), int(s % 60 + 0.5) }'; }

echo "$me: $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg), root $dir"
printf '%s: sources:\n' "$me"; printf '  %s\n' "${sources[@]}"

# 1. The new machine: minbase (Essential + Priority required + apt) and git, to clone with.
t0=$(now)
mmdebstrap --variant=minbase --include=git,ca-certificates bookworm "$dir" "${sources[@]}" >"$logs/mmdebstrap.log" 2>&1 || {
  tail -n 30 "$logs/mmdebstrap.log" >&2; echo "$me: mmdebstrap failed (log: $logs/mmdebstrap.log)" >&2; exit 1; }
t1=$(now)
echo "$me: minimal Debian 12 root made in $(mmss "$(echo "$t1 - $t0" | bc)") ($(chroot "$dir" dpkg-query -W | wc -l) packages)"
cp -L /etc/resolv.conf "$dir/etc/resolv.conf"

# 2. "From a clone of this repository": HEAD of this checkout, committed files only.
git clone -q --no-hardlinks "$repo" "$dir/root/ffx-dof"
echo "$me: cloned $(git -C "$dir/root/ffx-dof" log -1 --format='%h %s' | cut -c1-80)"

# Runs a command in the root as a fresh root login would: clean environment, /proc /sys /dev mounted in a
# private mount namespace (gone when the command ends).
in_root() {
  unshare --mount --fork -- bash -c '
    set -e
    mount --make-rprivate /
    mount -t proc proc "$1/proc"
    mount -t sysfs sysfs "$1/sys"
    mount --rbind /dev "$1/dev"
    root="$1"; shift
    exec chroot "$root" /usr/bin/env -i HOME=/root USER=root LOGNAME=root SHELL=/bin/bash TERM=dumb LANG=C.UTF-8 \
      PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin /bin/bash -c "cd /root/ffx-dof && $*"
  ' _ "$dir" "$@"
}

run_timed() { # $1 label, $2 command; prints the seconds taken on stdout's last line
  local t s rc=0
  t=$(now)
  in_root "$2" >"$logs/$1.log" 2>&1 || rc=$?
  s=$(echo "$(now) - $t" | bc)
  echo "$s $rc"
}

echo "$me: bash tools/demo.sh ... (log: $logs/demo.log)"
read -r demo_s demo_rc < <(run_timed demo "bash tools/demo.sh")
if [ "$demo_rc" -ne 0 ] || [ ! -s "$dir/root/ffx-dof/demo-out/side-by-side.png" ]; then
  tail -n 40 "$logs/demo.log" >&2
  echo "$me: FAILED: bash tools/demo.sh exited $demo_rc after $(mmss "$demo_s") (log: $logs/demo.log)" >&2
  exit 1
fi
echo "$me: demo OK in $(mmss "$demo_s"): $(ls "$dir/root/ffx-dof/demo-out" | tr '\n' ' ')"

echo "$me: bash tools/test.sh ... (log: $logs/test.log)"
read -r test_s test_rc < <(run_timed test "bash tools/test.sh")
if [ "$test_rc" -ne 0 ]; then
  tail -n 60 "$logs/test.log" >&2
  echo "$me: FAILED: bash tools/test.sh exited $test_rc after $(mmss "$test_s") (log: $logs/test.log)" >&2
  exit 1
fi
grep -E "tests passed|check-packages:|build-mingw: OK" "$logs/test.log" | sed 's/^/  /'

total=$(echo "$demo_s + $test_s" | bc)
echo
echo "$me: cold times on a fresh Debian 12 root ($(nproc) cores, load at end $(cut -d' ' -f1-3 /proc/loadavg)):"
echo "  new machine -> first picture   (bash tools/demo.sh):              $(mmss "$demo_s")"
echo "  then        -> green test run  (bash tools/test.sh):              $(mmss "$test_s")"
echo "  new machine -> green test run  (both commands, in README order):  $(mmss "$total")"
