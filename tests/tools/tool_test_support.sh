# Sourced by the tests of tools/*.sh: a work folder removed on exit, and checks that count their failures.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
expect() {  # expect NAME WANTED ACTUAL
  if [ "$2" != "$3" ]; then
    printf 'FAILED: %s\n  wanted: %s\n  got:    %s\n' "$1" "$2" "$3"
    failures=$((failures + 1))
  fi
}
check() {  # check NAME COMMAND...
  if ! "${@:2}" >/dev/null 2>&1; then
    echo "FAILED: $1"
    failures=$((failures + 1))
  fi
}
# The last line of a test: its verdict and exit status (`finish NAME`).
finish() {
  [ "$failures" = 0 ] && echo "$1: all checks passed"
  exit "$failures"
}
