# Shared by the download tests (sourced): a scratch folder removed on exit, the loopback
# servers they start, and `check`, which counts failures instead of stopping at the first.
# The sourcing script sets `here` (its folder) and `python` first.

# new_work_dir NAME: a fresh scratch folder in $work, removed with the servers on exit.
new_work_dir() {
  work="$(mktemp -d "${TMPDIR:-/tmp}/$1.XXXXXX")"
  servers=()
  trap 'for pid in "${servers[@]}"; do kill "$pid" 2>/dev/null || true; done; rm -rf "$work"' EXIT
}

failures=0
check() {  # check "what" command...
  local what="$1"
  shift
  if "$@"; then echo "ok   $what"; else echo "FAIL $what"; failures=$((failures + 1)); fi
}

# start_range_server ROOT [DROP]: range_server.py serving ROOT on 127.0.0.1 (dropping each
# connection after DROP bytes when DROP > 0); sets `url` and `log` (its request log).
start_range_server() {
  local root="$1" drop="${2:-0}"
  log="$work/requests_$RANDOM.log"
  : > "$log"
  "$python" "$here/range_server.py" --root "$root" --port-file "$work/port" --log "$log" \
    --drop-after "$drop" &
  servers+=($!)
  for _ in $(seq 100); do [[ -s "$work/port" ]] && break; sleep 0.1; done
  [[ -s "$work/port" ]] || { echo "FAIL the loopback server did not start" >&2; exit 1; }
  url="http://127.0.0.1:$(cat "$work/port")"
  rm -f "$work/port"
}
