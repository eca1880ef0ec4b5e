#!/usr/bin/env bash
# shellcheck disable=SC2016  # (backquotes in single quotes are Markdown)
# Tests the run store and staleness rules of scripts/results_document.sh: a stored run comes back
# on a clean checkout, an existing run is never overwritten, and a run is stale exactly when its
# build lacks a commit that changed what it measures. Needs the repository's history (exit 77 =
# skipped in a shallow clone).
set -euo pipefail
cd "$(dirname "$0")/../.."
source scripts/results_document.sh

TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

OUT=$TMP/out; STORE=$TMP/store
make_run() {  # make_run NAME BUILD
  mkdir -p "$OUT/$1/figures"
  echo '{"scans": 3}' >"$OUT/$1/summary.json"
  echo "scout replay x --out $OUT/$1" >"$OUT/$1/command.txt"
  echo "$2" >"$OUT/$1/build.txt"
  echo "round,strategy" >"$OUT/$1/frontier.csv"
  echo P5 >"$OUT/$1/map.pgm"
  echo '<svg></svg>' >"$OUT/$1/figures/p.svg"
}

head=$(git rev-parse --short=12 HEAD)
make_run replay-a "$head"
store_run replay-a
[[ -f $STORE/replay-a/summary.json && -f $STORE/replay-a/build.txt ]] || fail "summary not stored"
[[ -f $STORE/replay-a/figures/p.svg ]] || fail "a replay's figures are stored"
[[ ! -e $STORE/replay-a/map.pgm ]] || fail "large outputs are not stored"
[[ ! -e $STORE/replay-a.tmp ]] || fail "no temporary directory left"

# A clean checkout: the run comes back from the store.
rm -rf "$OUT"
restore_run replay-a
cmp -s "$OUT/replay-a/summary.json" "$STORE/replay-a/summary.json" || fail "run not restored"

# A run another scripts/results is making right now (its run_one holds OUT/logs/NAME.lock) is
# left alone; once the lock is released the stored run comes back.
rm -rf "$OUT/replay-a"
mkdir -p "$OUT/replay-a" "$OUT/logs"
echo partial >"$OUT/replay-a/being-made"
exec {held}>"$OUT/logs/replay-a.lock"
flock "$held"
restore_run replay-a
[[ -f $OUT/replay-a/being-made && ! -e $OUT/replay-a/summary.json ]] ||
  fail "restore replaced a run being made"
exec {held}>&-
restore_run replay-a
cmp -s "$OUT/replay-a/summary.json" "$STORE/replay-a/summary.json" ||
  fail "run not restored after its lock was released"

# A run whose re-run by another scripts/results was interrupted (its directory emptied, no
# summary, the lock released) comes back before the document is written.
rm -rf "$OUT/replay-a"
mkdir -p "$OUT/replay-a"
echo partial >"$OUT/replay-a/map.pgm"
restore_unfinished replay-a replay-absent
cmp -s "$OUT/replay-a/summary.json" "$STORE/replay-a/summary.json" ||
  fail "an interrupted re-run's stored run did not come back"
[[ ! -e $OUT/replay-absent ]] || fail "a run the store lacks was made up"

# A finished run in OUT is never replaced by the stored one.
echo '{"scans": 4}' >"$OUT/replay-a/summary.json"
restore_run replay-a
grep -q '"scans": 4' "$OUT/replay-a/summary.json" || fail "restore overwrote a finished run"

# store_finished stores changed runs, and skips runs whose build is not recorded.
store_finished replay-a
grep -q '"scans": 4' "$STORE/replay-a/summary.json" || fail "changed run not stored again"
# ... but not while its run_one holds the lock (that run_one stores it when it is done).
echo '{"scans": 5}' >"$OUT/replay-a/summary.json"
exec {held}>"$OUT/logs/replay-a.lock"
flock "$held"
store_finished replay-a
grep -q '"scans": 4' "$STORE/replay-a/summary.json" || fail "a run being made was stored"
exec {held}>&-
store_finished replay-a
grep -q '"scans": 5' "$STORE/replay-a/summary.json" || fail "run not stored after its lock was released"
make_run explore-b "$head"
rm "$OUT/explore-b/build.txt"
store_finished explore-b
[[ ! -e $STORE/explore-b ]] || fail "a run without build.txt was stored"

# The data's path is spelt relative to the repository however DATA is given, so a stored run's
# command matches on a clean checkout; a symbolic link is kept as spelt.
[[ $(canonical_data_path ../shared/data) == ../shared/data ]] || fail "relative DATA respelt"
[[ $(canonical_data_path "$PWD/../shared/data") == ../shared/data ]] ||
  fail "absolute DATA not spelt relative: $(canonical_data_path "$PWD/../shared/data")"
[[ $(canonical_data_path "$PWD/../shared//data/") == ../shared/data ]] || fail "DATA not normalised"
mkdir -p "$TMP/data"
ln -s "$TMP/data" "$TMP/link"
[[ $(canonical_data_path "$TMP/link") == */link ]] || fail "a link to the data was resolved"

# --jobs takes a positive number of runs; anything else stops before a run starts.
for bad in 0 -1 two ''; do
  status=0
  message=$(bash scripts/results --jobs "$bad" 2>&1) || status=$?
  [[ $status == 2 && $message == *"--jobs expects a positive integer"* ]] ||
    fail "--jobs '$bad' gave exit $status: $message"
done

# run_one makes a run beside the finished one it replaces and swaps them only when the new one
# has finished: a failed (or interrupted) run leaves the previous one for the document. Checked
# with a copy of the scripts and a stand-in scout that writes part of a run, then fails.
mkdir -p "$TMP/repo/scripts" "$TMP/repo/out/results-quick/explore-office-scout-1"
cp scripts/results scripts/results_document.sh "$TMP/repo/scripts/"
previous=$TMP/repo/out/results-quick/explore-office-scout-1
echo '{"previous": 1}' >"$previous/summary.json"
cat >"$TMP/fake-scout" <<'FAKE'
#!/bin/bash
[[ $1 == --version ]] && { echo "scout 0.1.0 (0123456789ab)"; exit 0; }
[[ $1 == report ]] && { echo "report of $2" >"$2/report.html"; exit 0; }
[[ $1 == explore ]] || exit 0
while [[ $# -gt 1 && $1 != --out ]]; do shift; done
mkdir -p "$2"
echo "part" >"$2/map.pgm"
[[ $FAKE_FAIL == 1 ]] && exit 1
echo '{"new": 1}' >"$2/summary.json"
FAKE
chmod +x "$TMP/fake-scout"
status=0
FAKE_FAIL=1 SCOUT=$TMP/fake-scout DATA=$TMP/no-data bash "$TMP/repo/scripts/results" --quick \
  --fresh --sections explore --only explore-office-scout-1 >"$TMP/fail.log" 2>&1 || status=$?
[[ $status == 1 ]] || fail "a failed run did not fail the evaluation (exit $status)"
grep -q '"previous"' "$previous/summary.json" || fail "a failed run replaced the finished one"
[[ -f $TMP/repo/out/results-quick/.making/explore-office-scout-1/map.pgm ]] ||
  fail "a failed run's partial outputs are not kept aside"
grep -q "what it wrote in out/results-quick/.making/explore-office-scout-1" "$TMP/fail.log" ||
  fail "the failure does not say where the partial outputs are: $(cat "$TMP/fail.log")"
# A run that finishes replaces the previous one, with its report drawn where it now is (the
# document written afterwards by the stand-in scout is not checked).
FAKE_FAIL=0 SCOUT=$TMP/fake-scout DATA=$TMP/no-data bash "$TMP/repo/scripts/results" --quick \
  --fresh --sections explore --only explore-office-scout-1 >"$TMP/ok.log" 2>&1 || true
grep -q '"new"' "$previous/summary.json" || fail "a finished run did not replace the previous one"
[[ ! -e $TMP/repo/out/results-quick/.making/explore-office-scout-1 ]] ||
  fail "a finished run was left in .making"
grep -q "^report of out/results-quick/explore-office-scout-1$" "$previous/report.html" ||
  fail "the report was not drawn again in the run's own directory"

if ! git cat-file -e "$FRONTIER_EXACT_COMMIT^{commit}" 2>/dev/null ||
  ! git cat-file -e "$FRONTIER_EXACT_COMMIT~1^{commit}" 2>/dev/null; then
  echo "SKIP: no history back to $FRONTIER_EXACT_COMMIT (shallow clone); staleness not tested"
  exit 77
fi
[[ -z $(stale_section_run bench replay-a) ]] || fail "a run made by HEAD is stale"
git rev-parse --short=12 "$FRONTIER_EXACT_COMMIT~1" >"$OUT/replay-a/build.txt"
[[ $(stale_section_run bench replay-a) == '`replay-a` ' ]] || fail "a run older than the commit is not stale"
git rev-parse --short=12 "$FRONTIER_EXACT_COMMIT" >"$OUT/replay-a/build.txt"
[[ -z $(stale_since "$FRONTIER_EXACT_COMMIT" replay-a) ]] || fail "a run made by the commit itself is stale"
echo "0123456789ab" >"$OUT/replay-a/build.txt"
[[ -n $(stale_since "$FRONTIER_EXACT_COMMIT" replay-a) ]] || fail "a run by an unknown build is not stale"
echo "$head +modified" >"$OUT/replay-a/build.txt"
[[ -z $(stale_since "$FRONTIER_EXACT_COMMIT" replay-a) ]] || fail "a modified build of HEAD is stale"
# Without build.txt, the summary's time decides.
rm "$OUT/replay-a/build.txt"
touch -d @0 "$OUT/replay-a/summary.json"
[[ -n $(stale_since "$FRONTIER_EXACT_COMMIT" replay-a) ]] || fail "an old run without build.txt is not stale"
# An explore run is stale when its build lacks the last commit that changed what the robot does.
make_run explore-c "$(git rev-parse --short=12 "$EXPLORE_BEHAVIOUR_COMMIT~1")"
[[ $(stale_section_run explore explore-c) == '`explore-c` ' ]] || fail "an explore run older than $EXPLORE_BEHAVIOUR_COMMIT is not stale"
git rev-parse --short=12 "$EXPLORE_BEHAVIOUR_COMMIT" >"$OUT/explore-c/build.txt"
[[ -z $(stale_section_run explore explore-c) ]] || fail "an explore run made by $EXPLORE_BEHAVIOUR_COMMIT is stale"
# A run whose input is absent is listed as skipped, with the missing file, not as failed.
declare -A COMMAND=([replay-b]="scout replay b" [replay-c]="scout replay c")
declare -A ABSENT=([replay-b]=/no/data/b.log.gz)
DATA=/no/data
listed=$(not_run replay-b replay-c)
grep -q '^\*\*Skipped, their input is absent' <<<"$listed" || fail "an absent input is not named"
grep -q '`replay-b`: `/no/data/b.log.gz`' <<<"$listed" || fail "the skipped run's file is not listed"
grep -q '^scout replay c$' <<<"$listed" || fail "a run that is missing for another reason is not listed"
grep -q '^scout replay b$' <<<"$listed" && fail "a skipped run is listed as not run"
# A run's build is the commit the binary names (scout --version), the tree's when it names none.
printf '#!/bin/sh\necho "scout 0.1.0 (0123456789ab +modified)"\n' >"$TMP/named"
printf '#!/bin/sh\necho "scout 0.1.0"\n' >"$TMP/unnamed"
chmod +x "$TMP/named" "$TMP/unnamed"
[[ $(binary_commit "$TMP/named") == "0123456789ab +modified" ]] || fail "the binary's own commit is not used"
[[ $(binary_commit "$TMP/unnamed") == "$(build_commit)" ]] || fail "a binary naming no commit is not given the tree's"
echo "results store: all checks passed"
