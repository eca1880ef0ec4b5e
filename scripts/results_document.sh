# shellcheck shell=bash disable=SC2016  # (backquotes in single quotes are Markdown)
# Sourced by scripts/results: writes $DOC and $FIG from the runs under $OUT. Every table comes
# from `scout results-table`, which prints the command of each run above it; runs that do not
# exist (not run yet, or failed) are listed as such with the command that would produce them.

# build_commit: the commit the tree is at, "+modified" when its sources differ from it (a run
# is then attributed to that commit, and the document says so).
build_commit() {
  local commit
  commit=$(git rev-parse --short=12 HEAD 2>/dev/null) || { echo unknown; return 0; }
  if [[ -n $(git status --porcelain -- src apps cmake config CMakeLists.txt 2>/dev/null) ]]; then
    echo "$commit +modified"
  else
    echo "$commit"
  fi
}

# binary_commit SCOUT: the commit the scout binary was built from, as its --version names it
# ("scout 0.1.0 (0123456789ab +modified)", written at build time by cmake/build_commit.cmake);
# build_commit, the tree's, for a binary built before it named its commit.
binary_commit() {
  local version
  version=$("$1" --version 2>/dev/null) || version=
  if [[ $version =~ \(([0-9a-f]{12}( \+modified)?|unknown)\)$ ]]; then
    echo "${BASH_REMATCH[1]}"
  else
    build_commit
  fi
}

# made_before COMMIT NAME: true when run NAME was made by a build that does not contain COMMIT.
# Runs without build.txt (made before it was recorded) are judged by the time of their summary.
made_before() {
  local commit=$1 f=$OUT/$2/build.txt built
  if [[ -f $f ]]; then
    built=$(cut -d' ' -f1 "$f")
    git cat-file -e "$built^{commit}" 2>/dev/null || return 0
    ! git merge-base --is-ancestor "$commit" "$built"
  else
    local since
    since=$(git log -1 --format=%ct "$commit" 2>/dev/null) || return 1
    (($(stat -c %Y "$OUT/$2/summary.json") < since))
  fi
}

# store_run NAME: copies run NAME's small outputs into $STORE/NAME (a replay's figures too, which
# the document embeds), replacing what was there.
store_run() {
  local name=$1 dir=$OUT/$1 f
  [[ -n $STORE ]] || return 0
  rm -rf "$STORE/$name.tmp"
  mkdir -p "$STORE/$name.tmp"
  for f in summary.json command.txt build.txt coverage.csv frontier.csv; do
    if [[ -f $dir/$f ]]; then cp "$dir/$f" "$STORE/$name.tmp/"; fi
  done
  if [[ $name == replay-* && -d $dir/figures ]]; then cp -r "$dir/figures" "$STORE/$name.tmp/"; fi
  rm -rf "${STORE:?}/$name"
  mv "$STORE/$name.tmp" "$STORE/$name"
}

# run_lock NAME: the file whose lock scripts/results' run_one holds while it makes run NAME.
run_lock() { echo "$OUT/logs/$1.lock"; }

# unless_being_made NAME COMMAND...: runs COMMAND, holding run NAME's lock, unless another
# scripts/results is making that run right now (then does nothing).
unless_being_made() {
  local name=$1 lock_fd
  shift
  mkdir -p "$OUT/logs"
  exec {lock_fd}>"$(run_lock "$name")"
  if flock -n "$lock_fd"; then "$@"; fi
  exec {lock_fd}>&-
}

# canonical_data_path PATH: PATH relative to the repository (../shared/data on the usual layout).
# Runs are kept when their command is unchanged, so the data's path is always spelt the same
# way, however DATA was given: otherwise the stored runs made with DATA=/abs/path would all be
# made again from a clean checkout. Symbolic links are kept as spelt (a checkout beside a link to
# the data).
canonical_data_path() {
  realpath -m -s --relative-to=. "$1"
}

# restore_run NAME: when $OUT/NAME has no finished run, copies the stored one there.
restore_run() {
  local name=$1
  [[ -n $STORE && -f $STORE/$name/summary.json && -f $STORE/$name/command.txt ]] || return 0
  [[ -f $OUT/$name/summary.json && -f $OUT/$name/command.txt ]] && return 0
  unless_being_made "$name" copy_stored_run "$name"
}
copy_stored_run() {
  rm -rf "${OUT:?}/$1"
  cp -r "$STORE/$1" "$OUT/$1"
}

# restore_unfinished NAME...: restore_run for each run, again just before the document is written.
# A run another scripts/results was making when this one started was not restored then (its lock
# was held); if that run was interrupted, or its directory emptied by a scripts/results older than
# run_one's .making/, the document would leave out a run the store has.
restore_unfinished() {
  local name
  for name in "$@"; do restore_run "$name"; done
}

# builds_note NAME...: which builds made the finished runs, so a reader sees what is mixed.
builds_note() {
  local name f
  for name in "$@"; do
    f=$OUT/$name/build.txt
    [[ -f $OUT/$name/summary.json ]] || continue
    if [[ -f $f ]]; then cat "$f"; else echo "not recorded"; fi
  done | sort | uniq -c | sort -rn | awk '{c=$1; $1=""; sub(/^ /,""); printf "%s`%s` (%d run%s)", (NR>1?", ":""), $0, c, (c==1?"":"s")} END {if (NR) print ""}'
}

# existing NAME...: prints the directories of the runs that finished.
existing() {
  local name
  for name in "$@"; do
    if [[ -f $OUT/$name/summary.json && -f $OUT/$name/command.txt ]]; then echo "$OUT/$name"; fi
  done
}

# not_run NAME...: a list of the runs that have no results, with their commands.
not_run() {
  local name missing=() absent=()
  for name in "$@"; do
    [[ -f $OUT/$name/summary.json && -f $OUT/$name/command.txt ]] && continue
    if [[ -n ${ABSENT[$name]:-} ]]; then absent+=("$name"); else missing+=("$name"); fi
  done
  if [[ ${#absent[@]} -gt 0 ]]; then
    echo "**Skipped, their input is absent (DATA=\`$DATA\`; see \`../shared/data/README.md\`):**"
    echo
    for name in "${absent[@]}"; do echo "- \`$name\`: \`${ABSENT[$name]}\`"; done
    echo
  fi
  [[ ${#missing[@]} -eq 0 ]] && return 0
  echo "**Not run (or failed; see \`$OUT/logs/\`):**"
  echo
  echo '```sh'
  for name in "${missing[@]}"; do echo "${COMMAND[$name]}"; done
  echo '```'
  echo
}

# tables KIND NAME...: the Markdown tables of the finished runs, then the missing ones.
# The last commit that changed what an explore run does. Runs whose summary
# is older than it came from an earlier build; stale_runs NAME... lists them,
# so a table never silently mixes builds.
# f48c5a4: loop closures farther from the estimate than the search window of their chain of
# submaps and loop closures are rejected. It changes the runs in which such a match came up,
# which an older summary does not record (a newer one counts them, slam.gated_loop_closures),
# so every older explore run is stale. Before it, conditional rules here spared older runs
# that the commits since aa6452d could not have changed (those with no stuck recovery, guard
# stop, reachable frontier left or no-progress timeout, or of another policy): d725b7b and
# 8a6e5c2 (stuck recoveries), 137c2f9 (failed goals retried), 216716d and 2c431ab (guard
# stops), 512946f (information gain 1), d13fac7 and 9847fb7 (the scan check), 428423a (the last
# resort), d4f3d46 (backing up); f48c5a4 makes them all moot (see git history for the rules).
# 27905ca: the explorer's loop-closure search keeps near matches (fbdb285), which it had kept
# off; any run may close different loops, so every older explore run is stale. (8b61b43 turned
# them off again and 25f9950 back on: no stored run came from a build in between, whose near
# matches were off although it contains 27905ca.)
EXPLORE_BEHAVIOUR_COMMIT=27905ca
stale_runs() {
  local name
  for name in "$@"; do
    [[ -f $OUT/$name/summary.json ]] || continue
    if made_before "$EXPLORE_BEHAVIOUR_COMMIT" "$name"; then printf '`%s` ' "$name"; fi
  done
  return 0
}

# b77b701: exact follows one witness per point that is not a frontier. It answers as before
# (always as full) but queries fewer points, with different times, so a replay or frontier-bench run
# older than it reports the earlier exact. ad112e7: exact drops the entries of points a watch no
# longer tracks and keeps one per point (same answers, fewer points re-queried, less time).
# 55f8ae9: exact proves points outside the other submap's box without a look-up (same answers,
# fewer points re-queried).
FRONTIER_EXACT_COMMIT=55f8ae9
# stale_since COMMIT NAME...: the finished runs whose build does not contain COMMIT.
stale_since() {
  local commit=$1 name
  shift
  for name in "$@"; do
    [[ -f $OUT/$name/summary.json ]] || continue
    if made_before "$commit" "$name"; then printf '`%s` ' "$name"; fi
  done
  return 0
}

# 6c5133f: loop closures in thin submaps judged against their own scans (f236b19, then the
# ambiguity margin), which changes the Radish replays' SLAM; 560cef9 added the consistency
# measure. A replay run older than it is redone. (93a957a's chained search windows are off by
# default, so replays are unchanged.) 0c4defc: replays match scans on the submaps' likelihood
# field; the explorer keeps the probabilities (explore.local_slam), so explore runs are unchanged.
# f48c5a4: loop closures gated by their chain (synchronous replays, seeds 1-3: fhw seed 1 finds
# 82 closures instead of 85, aces seed 3, csail seed 2 and fhw seed 3 move by 0.001-0.004 m).
# fa1aba6: the real-time matcher keeps the prediction when its best turn is on the angular window's
# edge (4 of 96 Radish runs, seeds 1-12, change; seed 1 and the bag do not: they are redone anyway).
# 4d106d6: a second real-time search after a surprising match; bc53de6 moved its threshold from
# 10 to 15 deg (seeds 1-12: 9 csail runs change, no other run and not the bag). 55fb98f added the
# revisit consistency (SLAM unchanged: seeds 1-12 and the bag give the same ATE to the digit).
# fbdb285: near matches in the loop-closure search (every replay changes but orebro's; the
# explorer keeps them off, explore.near_match_max_innovation_m, so explore runs are unchanged).
REPLAY_SLAM_COMMIT=fbdb285
# stale_section_run SECTION NAME: prints NAME if a commit after its build changed its result.
stale_section_run() {
  case $1 in
    explore) stale_runs "$2" ;;
    replay) stale_since "$FRONTIER_EXACT_COMMIT" "$2"; stale_since "$REPLAY_SLAM_COMMIT" "$2" ;;
    *) stale_since "$FRONTIER_EXACT_COMMIT" "$2" ;;
  esac
}

# stale_note NAME...: a paragraph naming the frontier runs made before FRONTIER_EXACT_COMMIT.
stale_note() {
  local stale
  stale=$(stale_since "$FRONTIER_EXACT_COMMIT" "$@")
  [[ -z $stale ]] && return 0
  echo "Made with a build older than commit $FRONTIER_EXACT_COMMIT (\`exact\` skips the look-ups a box proves),"
  echo "so their \`exact\` rows show the earlier \`exact\` (the same answers, with more points"
  echo "re-queried and more time per round): $stale"
  echo
}

tables() {
  local kind=$1; shift
  local dirs
  mapfile -t dirs < <(existing "$@")
  if [[ ${#dirs[@]} -gt 0 ]]; then
    "$SCOUT" results-table --kind "$kind" "${dirs[@]}"
  fi
  not_run "$@"
}

# figures PREFIX SOURCE_DIR: copies SOURCE_DIR/*.svg to $FIG/PREFIX-*.svg and embeds them.
figures() {
  local prefix=$1 src=$2 svg base
  [[ -d $src ]] || return 0
  for svg in "$src"/*.svg; do
    [[ -f $svg ]] || continue
    base=$(basename "$svg" .svg)
    cp "$svg" "$FIG/$prefix-$base.svg"
    echo "![$prefix $base](figures/$prefix-$base.svg)"
    echo
  done
}

# compare_figures PREFIX NAME...: `scout compare` of the finished runs, figures embedded.
compare_figures() {
  local prefix=$1; shift
  local dirs
  mapfile -t dirs < <(existing "$@")
  [[ ${#dirs[@]} -ge 1 ]] || return 0
  rm -rf "$OUT/compare-$prefix"
  "$SCOUT" compare "${dirs[@]}" --out "$OUT/compare-$prefix" >/dev/null
  echo "Figures: \`scout compare ${dirs[*]} --out $OUT/compare-$prefix\`"
  echo
  figures "$prefix" "$OUT/compare-$prefix/figures"
}

# sweep_figures PREFIX NAME...: the ε / world-size figures of `scout results-table --figures`.
sweep_figures() {
  local prefix=$1; shift
  local dirs
  mapfile -t dirs < <(existing "$@")
  [[ ${#dirs[@]} -ge 2 ]] || return 0
  rm -rf "$OUT/figures-$prefix"
  "$SCOUT" results-table --kind bench "${dirs[@]}" --figures "$OUT/figures-$prefix" >/dev/null
  figures "$prefix" "$OUT/figures-$prefix"
}

# explore_figures NAME...: one `scout compare` per world (explore-WORLD-POLICY-SEED), whose
# coverage figures draw one line per goal policy, the mean over its seeds.
explore_figures() {
  local name tag p prefix tags=() runs
  for name in "$@"; do
    tag=${name#explore-}; tag=${tag%-*}
    for p in scout nearest explore-lite meanshift-centres; do
      [[ $tag == *-$p ]] && tag=${tag%-"$p"}
    done
    [[ " ${tags[*]} " == *" $tag "* ]] || tags+=("$tag")
  done
  for tag in "${tags[@]}"; do
    runs=()
    for name in "$@"; do [[ $name == explore-$tag-* ]] && runs+=("$name"); done
    prefix=explore-$tag; [[ $tag == office ]] && prefix=explore
    [[ -n $(existing "${runs[@]}") ]] || continue
    echo "### Coverage: $tag"
    echo
    compare_figures "$prefix" "${runs[@]}"
  done
}

# store_finished NAME...: stores every finished run with a recorded build the store lacks or holds
# in another version (runs made before the store existed, or by an interrupted script).
store_finished() {
  local name
  [[ -n $STORE ]] || return 0
  for name in "$@"; do
    [[ -f $OUT/$name/summary.json && -f $OUT/$name/command.txt && -f $OUT/$name/build.txt ]] ||
      continue
    cmp -s "$OUT/$name/summary.json" "$STORE/$name/summary.json" && continue
    # A run still being made is stored by its own run_one when it is done.
    unless_being_made "$name" store_run "$name"
  done
}

write_document() {
  local all=("${REPLAY[@]}" "${EXPLORE[@]}" "${EPS[@]}" "${SIZE[@]}" "${BENCH[@]}") lock_fd
  # Two scripts/results at once (runs started separately, or --doc-only beside a running
  # evaluation) share the document, its temporary file and the figures: one writes at a time.
  exec {lock_fd}>"$OUT/.document.lock"
  flock "$lock_fd"
  restore_unfinished "${all[@]}"
  store_finished "${all[@]}"
  rm -rf "$FIG"
  mkdir -p "$FIG" "$(dirname "$DOC")"
  local first_run=${REPLAY[0]}
  {
    echo "# Scout results"
    echo
    echo "Generated by \`scripts/results$([[ $QUICK == 1 ]] && echo ' --quick')\` on $(date -u +%Y-%m-%d)"
    echo "(\`make results$([[ $QUICK == 1 ]] && echo '-quick')\`) from the runs in \`$OUT/\`, on"
    echo "$(nproc) cores shared with other jobs ($(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'))."
    echo "\`scout\` is \`$SCOUT\`. Every table lists the command of each of its runs;"
    echo "runs that did not finish are listed under **Not run**. Times are wall-clock on a shared"
    echo "machine: compare them within a table, not across tables. Figures in \`$FIG/\`."
    if [[ -n $STORE ]]; then
      echo "Each run's small outputs are kept in \`$STORE/\` (summary, command, build, CSVs), so"
      echo "the document can be rewritten from a clean checkout; a run is redone only when a later"
      echo "commit changed what it measures. Builds that made these runs (commit, runs):"
      echo "$(builds_note "${all[@]}")."
    fi
    echo
    echo "Column meanings: *points re-queried* is summed over all optimisation rounds; *P* ="
    echo "1 − points(strategy) / points(dfd); *accuracy*, *precision*, *recall* and *wrong answers*"
    echo "compare every local frontier point's answer with \`full\` after every round;"
    echo "*ms per round* is the strategy's own update time per optimisation round."
    echo
    echo "## (a) Real data: replay through Scout's SLAM, all strategies in lockstep"
    echo
    echo "The Freiburg 079 bag carries raw wheel odometry and is scored against the corrected"
    echo "CARMEN log; the other Radish logs are already corrected, so they are replayed with injected"
    echo "odometry drift (\`--odom-noise 1 --seed 1\`) and scored against their own poses."
    echo
    stale_note "${REPLAY[@]}"
    tables replay "${REPLAY[@]}"
    compare_figures replay "${REPLAY[@]}"
    if [[ -f $OUT/$first_run/summary.json ]]; then
      echo "Per-round figures of \`$first_run\` (from its \`figures/\`):"
      echo
      figures "$first_run" "$OUT/$first_run/figures"
    fi
    echo "## (b) Closed-loop exploration"
    echo
    echo "Each run: the simulated robot (180° lidar, drifting odometry) explores with Scout's SLAM"
    echo "in the loop, strategy \`exact\`, one goal policy. *coverage* is the reachable free area"
    echo "mapped correctly, with the map placed in the world by the rigid fit of the estimated"
    echo "trajectory to the true one (as for the ATE); *path to 99 %* is the path length when coverage"
    echo "first reached 99 % (— = never; the per-policy table also gives 95 %, which compares the"
    echo "policies where map error keeps the last per cent out of reach: a wall drawn a few cm off"
    echo "leaves the cells along it unmatched); *unreachable* counts goals whose target (where the robot was"
    echo "sent, up to 0.5 m before the navigation point) the true world makes unreachable for the robot"
    echo "disc, placed where the scans that mapped it put it (relative to the true pose of the node"
    echo "nearest to it in a submap that knows it; each is listed with its position in the run's"
    echo "\`summary.json\`); *ATE* is the"
    echo "estimated trajectory against the simulator's. A run ends \`complete\` when no navigation"
    echo "point is left and at most 0.5 m of frontier a plan reaches remains away from goals the"
    echo "robot reached (frontier that stayed where it went is counted as \`visited_frontier_left\`),"
    echo "\`no_progress\` when the policy gave up on reachable frontier or the robot's own map gained"
    echo "less than 1 m² of free area in 300 s (\`max_sim_time\` after 3600 s of simulated time)."
    echo
    local stale
    stale=$(stale_runs "${EXPLORE[@]}")
    if [[ -n $stale ]]; then
      echo "Made with a build older than commit $EXPLORE_BEHAVIOUR_COMMIT, the last that changed what"
      echo "every policy's robot does or how runs are scored (see \`scripts/results_document.sh\`;"
      echo "$EXPLORE_BEHAVIOUR_COMMIT: the loop-closure search keeps near matches, matches scoring from 0.75"
      echo "of the minimum score that land within 0.3 m of the estimate, which the explorer had kept"
      echo "off), so not like-for-like with the other runs: $stale"
      echo
    fi
    tables explore "${EXPLORE[@]}"
    echo "Why the two centre-seeking baselines stop early (\`no_progress\` with reachable frontier"
    echo "left): their goals are centres of frontier pieces, not frontier cells. A centre often lies"
    echo "in unknown space or behind a wall, where no plan reaches it (\`goals.no_plan\` in a run's"
    echo "\`summary.json\`), or in space the robot maps on its way, so the goal is dropped before"
    echo "arrival (\`goals.seen_before_arrival\`); explore-lite's centroid of a piece that curves"
    echo "round the robot (in the museum's open halls, the ring where the start's free rays end) is"
    echo "where the robot already stands. Such goals are set aside until the map around them"
    echo "changes, and when only they are left the run stops. Scout's policy and nearest send the"
    echo "robot to frontier cells themselves. (\`docs/EXPERIMENTS.md\` traces single runs.)"
    echo
    explore_figures "${EXPLORE[@]}"
    echo "## (c) ε sweep (bfs, direct) on the frontier-bench office"
    echo
    echo "\`exact\`, \`dfd\` and \`full\` do not depend on ε; they are kept in the table as references."
    echo
    stale_note "${EPS[@]}"
    tables bench "${EPS[@]}"
    sweep_figures epsilon "${EPS[@]}"
    echo "## (d) Per-round frontier cost against world size"
    echo
    echo "Generated square museums (grids of halls, which scale; the office's inner block would"
    echo "become one huge room) of growing side, one seed. Up to 100 m, frontier-bench also runs"
    echo "\`full\` as the truth (accuracy columns); its cost grows fastest (182 of the 252 s at"
    echo "100 m), so larger worlds run with \`--no-reference\`, the strategies without it."
    echo "\`dfd\`, which re-queries every point every round, grows next fastest (2867 of the 4732 s"
    echo "at 350 m): the 500 m world runs \`bfs\`, \`direct\` and \`exact\` only. Its P is against what"
    echo "\`dfd\` would have queried, every local frontier point of every round (\`frontier.csv\`'s"
    echo "\`local_points\`; at 350 m their sum equals dfd's count, 67,752,512,197)."
    echo
    echo "*ms per round* is measured in lockstep (wall time), beside the other strategies of the run."
    echo "All five runs were made again on 2026-12-05 with build d5cb795, which has 55f8ae9 (exact"
    echo "proves the points outside another submap's box without a look-up) and ad112e7 (exact drops"
    echo "the entries its watches no longer need): the 350 and 500 m runs side by side on the two"
    echo "cores (with other jobs part of the time), the 50, 100 and 200 m runs two at a time. Exact's"
    echo "rounds take 1.27, 3.33, 8.14, 31.2 and 50.0 ms against bfs's 2.65, 6.79, 15.0, 50.6 and"
    echo "81.7 (0.48-0.62x) while re-querying 79x, 143x, 186x, 271x and 307x fewer points. Before"
    echo "ad112e7 (builds 354b325, 024ad83 and bd59cdf) exact took 1.30, 4.99 and 13.2 ms against"
    echo "bfs's 1.85, 6.43 and 14.4 up to 200 m but was slower at 350 and 500 m: 62.5 against 46.0"
    echo "and 119.7 against 75.7 ms (1.36x and 1.58x), querying 29x fewer points there."
    echo
    stale_note "${SIZE[@]}"
    tables bench "${SIZE[@]}"
    sweep_figures size "${SIZE[@]}"
    if [[ ${#BENCH[@]} -gt 0 ]]; then
      echo "## Museum-scale synthetic stream (the paper's museum scene)"
      echo
      stale_note "${BENCH[@]}"
      tables bench "${BENCH[@]}"
    fi
    cat docs/results_paper.md
  } >"$DOC.tmp"
  mv "$DOC.tmp" "$DOC"
  exec {lock_fd}>&-
}

# check_document: the quick run must have produced tables for every section and figures.
check_document() {
  local n expected=6
  local figures=(epsilon-epsilon_points epsilon-epsilon_accuracy size-size_points size-size_time
    explore-compare_coverage_path)
  # The replay's two tables and its figure need a Radish log of ../shared/data.
  if [[ -n ${ABSENT[replay-intel]:-} ]]; then expected=4; else figures+=(replay-compare_p); fi
  n=$(grep -c '^| run |' "$DOC" || true)
  [[ $n -ge $expected ]] ||
    { echo "results: $DOC has $n tables, expected >= $expected" >&2; exit 1; }
  if grep -q '^\*\*Not run' "$DOC"; then echo "results: $DOC lists runs as not run" >&2; exit 1; fi
  for f in "${figures[@]}"; do
    grep -q '</svg>' "$FIG/$f.svg" 2>/dev/null || { echo "results: $FIG/$f.svg missing" >&2; exit 1; }
  done
  echo "results: $DOC: $n tables, $(ls "$FIG" | wc -l) figures"
}
