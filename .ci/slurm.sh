#!/usr/bin/env bash
# CI: the cluster job files on a real Slurm. Installs Debian's Slurm (slurmctld, slurmd,
# slurm-client) and munge, starts a private single-node cluster on this machine (its own config,
# ports, munge socket and state under a temporary folder; nothing in /etc is changed), submits
# docs/cluster/submit.sh (a 4-task array of experiment.sbatch, then merge.sbatch with
# --dependency=afterok) on a small suite, waits, and compares the merged result with a
# single-machine run of the same experiment; then again with one task killed part-way and
# re-submitted alone (it must resume). Stops everything it started. Prints one
# "slurm: PASSED" or "slurm: FAILED: why" line; exits non-zero on failure. Takes 1-3 minutes.
set -uo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
W=""
started_pids=()
sudo=""

say() { echo "slurm: $*"; }

cleanup() {
    if [ -n "$W" ] && [ -f "$W/slurm.conf" ]; then
        timeout 20 $sudo env SLURM_CONF="$W/slurm.conf" scontrol shutdown >/dev/null 2>&1
        sleep 1
    fi
    # Whatever did not stop: only the daemons this script started, by their pid (checking the
    # pid still names that daemon).
    for pid in "${started_pids[@]}"; do
        case "$(ps -p "$pid" -o comm= 2>/dev/null)" in
            munged|slurmctld|slurmd) $sudo kill "$pid" 2>/dev/null ;;
        esac
    done
    if [ -n "$W" ] && [ -z "${KEEP_SLURM_DIR:-}" ]; then $sudo rm -rf "$W"; fi
}
trap cleanup EXIT

fail() {
    say "FAILED: $*"
    if [ -n "$W" ]; then
        for log in "$W"/log/*.log "$W"/jobs/*.out; do
            [ -f "$log" ] || continue
            echo "----- $log (last 30 lines)"
            tail -30 "$log"
        done
    fi
    exit 1
}

# --- install -------------------------------------------------------------------------------
if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || fail "not root and no sudo: cannot install or start Slurm"
    sudo="sudo"
fi
need=()
for cmd in slurmctld:slurmctld slurmd:slurmd sbatch:slurm-client munged:munge; do
    command -v "${cmd%%:*}" >/dev/null || need+=("${cmd#*:}")
done
if [ ${#need[@]} -gt 0 ]; then
    say "installing ${need[*]}"
    $sudo apt-get update -qq >/dev/null || fail "apt-get update failed"
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${need[@]}" >/dev/null \
        || fail "apt-get install ${need[*]} failed"
fi
say "Slurm $(dpkg-query -W -f='${Version}' slurm-client 2>/dev/null), munge $(dpkg-query -W -f='${Version}' munge 2>/dev/null)"

# --- build the launcher the job scripts call --------------------------------------------------
gradle --no-daemon -q --console=plain installDist >/tmp/minigolf-slurm-build.log 2>&1 \
    || { cat /tmp/minigolf-slurm-build.log; fail "gradle installDist failed"; }
minigolf="$root/build/install/minigolf/bin/minigolf"
[ -x "$minigolf" ] || fail "no launcher at $minigolf"

# --- a private single-node cluster -----------------------------------------------------------
W=$(mktemp -d /tmp/minigolf-slurm.XXXXXX) || fail "mktemp failed"
chmod 755 "$W"
mkdir -p "$W/state" "$W/spool" "$W/log" "$W/munge" "$W/jobs"
chmod 755 "$W/munge"    # munged wants its socket's folder searchable by everyone, writable by none
dd if=/dev/urandom of="$W/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$W/munge/munge.key"
[ -n "$sudo" ] && { $sudo chown root "$W/munge/munge.key" || fail "cannot hand the munge key to root"; }   # munged wants its own key
$sudo munged --force --socket="$W/munge/socket" --key-file="$W/munge/munge.key" \
    --log-file="$W/log/munged.log" --pid-file="$W/munge/munged.pid" --seed-file="$W/munge/seed" \
    || fail "munged did not start"
started_pids+=("$(cat "$W/munge/munged.pid")")

free_port() {   # the first port from $1 on that nothing listens to
    local p=$1
    while (exec 3<>"/dev/tcp/127.0.0.1/$p") 2>/dev/null; do p=$((p + 1)); done
    echo "$p"
}
ctld_port=$(free_port 16817)
slurmd_port=$(free_port $((ctld_port + 1)))
host=$(hostname -s)
# The node as slurmd sees this machine (CPUs, sockets, memory), so the config cannot disagree.
node=$(slurmd -C 2>/dev/null | grep '^NodeName=') || fail "slurmd -C printed no node line"
cat >"$W/slurm.conf" <<EOF
ClusterName=minigolfci
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
AuthType=auth/munge
AuthInfo=socket=$W/munge/socket
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$W/state
SlurmdSpoolDir=$W/spool
SlurmctldPidFile=$W/slurmctld.pid
SlurmdPidFile=$W/slurmd.pid
SlurmctldLogFile=$W/log/slurmctld.log
SlurmdLogFile=$W/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
ReturnToService=2
MinJobAge=600
$node NodeAddr=127.0.0.1 State=UNKNOWN
PartitionName=ci Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF="$W/slurm.conf"
$sudo slurmctld -f "$W/slurm.conf" || fail "slurmctld did not start"
sleep 1
[ -f "$W/slurmctld.pid" ] && started_pids+=("$(cat "$W/slurmctld.pid")")
$sudo slurmd -f "$W/slurm.conf" || fail "slurmd did not start"
sleep 1
[ -f "$W/slurmd.pid" ] && started_pids+=("$(cat "$W/slurmd.pid")")
for _ in $(seq 60); do
    state=$(sinfo -h -n "$host" -o %T 2>/dev/null)
    [ "$state" = "idle" ] && break
    sleep 1
done
[ "$state" = "idle" ] || fail "the node did not become idle (state '$state')"
say "single-node cluster up: $host, $(sinfo -h -o '%c CPUs') (ports $ctld_port/$slurmd_port)"

# --- the experiment, through the documented job files ------------------------------------------
mkdir -p "$W/suite"
for c in flat-7m two-putt pond; do cp "courses/bench/$c.json" "$W/suite/"; done
seeds=16
runs=$((3 * 3 * seeds))
args="--bots planner,astar,newton --seeds $seeds"
cd "$W/jobs" || fail "no jobs folder"
sbatch_opts=(--cpus-per-task=1 --mem=512M --time=10)
export MINIGOLF="$minigolf" JAVA_OPTS="-Xmx384m" EXPERIMENT_ARGS="$args"

job_state() { scontrol show job "$1" 2>/dev/null | grep -o 'JobState=[A-Z_]*' | cut -d= -f2 | sort -u | tr '\n' ' '; }
# Waits until job $1 (all its array tasks) has ended, 4 minutes at most.
wait_end() {
    local deadline=$((SECONDS + 240)) s
    while [ $SECONDS -lt $deadline ]; do
        s=$(job_state "$1")
        [ -n "$s" ] && ! [[ "$s" =~ PENDING|RUNNING|CONFIGURING|COMPLETING|REQUEUED|SUSPENDED ]] && return
        sleep 1
    done
}
# Waits until job $1 has ended; fails unless every task of it ended as $2.
wait_job() {
    wait_end "$1"
    local s
    s=$(job_state "$1")
    [ "$s" = "$2 " ] || fail "job $1 ended '$s', expected $2 (after 4 minutes at most)"
}
submit() {   # submit.sh into $1; sets array and merge
    local submitted
    submitted=$(SUITE="$W/suite" OUT="$1" SHARDS=4 "$root/docs/cluster/submit.sh" "${sbatch_opts[@]}") \
        || fail "submit.sh failed: $submitted"
    echo "$submitted"
    array=$(echo "$submitted" | sed -n 's/.*array job \([0-9]*\).*/\1/p')
    merge=$(echo "$submitted" | sed -n 's/.*merge job \([0-9]*\).*/\1/p')
    [ -n "$array" ] && [ -n "$merge" ] || fail "could not read the job ids from submit.sh"
}
rows_in() { if [ -f "$1" ]; then echo $(($(wc -l <"$1") - 1)); else echo 0; fi; }   # complete rows, less the header

# 1. submit.sh: 4 array tasks, then the merge with --dependency=afterok.
submit "$W/exp"
wait_job "$array" COMPLETED
tasks=$(scontrol show job "$array" 2>/dev/null | grep -c '^JobId=')
[ "$tasks" -eq 4 ] || fail "expected 4 array tasks, Slurm shows $tasks"
wait_job "$merge" COMPLETED
for k in 0 1 2 3; do
    [ "$(rows_in "$W/exp/shard-$k-of-4/runs.csv")" -eq $((runs / 4)) ] || fail "shard $k/4 has $(rows_in "$W/exp/shard-$k-of-4/runs.csv") rows, expected $((runs / 4))"
done
say "array job $array: 4 tasks COMPLETED; merge job $merge (afterok) COMPLETED"

# 2. The same experiment again, with task 1 killed part-way (SIGKILL): the merge is cancelled
#    (--kill-on-invalid-dep), task 1 is re-submitted alone (SHARDS=4, as docs/cluster.md says),
#    resumes from its rows, and the merge is submitted again.
submit "$W/exp2"
log1="$W/exp2/shard-1-of-4/runs.csv"
deadline=$((SECONDS + 120))
while [ "$(rows_in "$log1")" -lt 3 ] && [ $SECONDS -lt $deadline ]; do sleep 0.2; done
scancel --signal=KILL "${array}_1" || fail "scancel failed"
killed_at=$(rows_in "$log1")
[ "$killed_at" -ge 3 ] && [ "$killed_at" -lt $((runs / 4)) ] \
    || fail "task 1 was not killed part-way ($killed_at of $((runs / 4)) rows; make the suite slower?)"
wait_job "$merge" CANCELLED
wait_end "$array"
states=$(scontrol show job "$array" 2>/dev/null | grep -o 'JobState=[A-Z_]*' | cut -d= -f2 | sort | uniq -c | tr -s ' \n' ' ')
[ "$(scontrol show job "$array" 2>/dev/null | grep -c 'JobState=COMPLETED')" -eq 3 ] \
    || fail "the other 3 tasks of array $array did not all complete:$states"
say "task ${array}_1 killed with $killed_at of $((runs / 4)) rows written; merge job $merge cancelled by the failed dependency; array:$states"
again=$(SUITE="$W/suite" OUT="$W/exp2" SHARDS=4 sbatch --parsable --array=1 "${sbatch_opts[@]}" \
    "$root/docs/cluster/experiment.sbatch") || fail "re-submitting task 1 failed"
again=${again%%;*}
merge2=$(OUT="$W/exp2" sbatch --parsable --dependency="afterok:$again" "${sbatch_opts[@]}" "$root/docs/cluster/merge.sbatch") \
    || fail "submitting the merge again failed"
merge2=${merge2%%;*}
wait_job "$again" COMPLETED
wait_job "$merge2" COMPLETED
grep -q "shard 1/4, $((runs / 4)) runs, [1-9][0-9]* done before" "$W/jobs/minigolf-experiment-${again}_1.out" \
    || { cat "$W/jobs/minigolf-experiment-${again}_1.out"; fail "the re-submitted task did not resume from its rows"; }
say "re-submitted task $again resumed ($(grep -o '[0-9]* done before' "$W/jobs/minigolf-experiment-${again}_1.out")); merge job $merge2 COMPLETED"

# --- compare with one machine's run ------------------------------------------------------------
# shellcheck disable=SC2086
JAVA_OPTS="-Xmx512m" "$minigolf" experiment --suite "$W/suite" --out "$W/single" $args >"$W/single.out" 2>&1 \
    || { cat "$W/single.out"; fail "the single-machine run failed"; }
no_wall() { sed 's/,[^,]*$//' "$1"; }                          # results.csv less its wall_ms column
no_time() { awk -F'|' 'BEGIN{OFS="|"} /^\| / && !/^\| course/ {$8=" ms "} {print}' "$1"; }   # summary.md less median ms
for merged in "$W/exp/merged" "$W/exp2/merged"; do
    rows=$(rows_in "$merged/results.csv")
    [ "$rows" -eq "$runs" ] || fail "$merged/results.csv has $rows rows, expected 3 courses x 3 bots x $seeds seeds = $runs"
    diff <(no_wall "$W/single/results.csv") <(no_wall "$merged/results.csv") >"$W/diff.txt" \
        || { cat "$W/diff.txt"; fail "$merged/results.csv differs from the single run's (beyond wall_ms)"; }
    diff <(no_time "$W/single/summary.md") <(no_time "$merged/summary.md") >"$W/diff.txt" \
        || { cat "$W/diff.txt"; fail "$merged/summary.md differs from the single run's (beyond times)"; }
    for f in simulations.png success.png experiment.json; do
        cmp -s "$W/single/$f" "$merged/$f" || fail "$merged/$f differs from the single run's"
    done
done
say "PASSED: on Slurm $(sbatch --version | cut -d' ' -f2), 4 array tasks + afterok merge, and the same with a task killed and re-submitted, both equal the single-machine run ($runs runs; results.csv, summary.md, charts, experiment.json)"
