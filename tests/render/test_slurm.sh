#!/bin/sh
# test_slurm.sh: raygl2pov --submit on a real one-node Slurm cluster.
#
#   test_slurm.sh RAYGL2POV RAYGL_RENDER MKANIM IMGCMP
#
# Starts munged (its own key and socket), slurmctld and slurmd (-D, as
# root) from a slurm.conf written into a temporary folder, on free ports;
# submits a small trace's frames as a job array; waits (bounded) for the
# array to finish; checks that every PNG appeared and matches a local render
# pixel for pixel; stops the daemons, also on failure. Skipped (77) when not
# root or when Slurm and munge are not installed (tools/deps.sh installs
# them) or the daemons do not start.
. "$(dirname "$0")/common.sh"

skip() {
    echo "SKIP: $*"
    exit 77
}
[ "$(id -u)" -eq 0 ] || skip "slurmctld and slurmd must run as root (running as $(id -un))"
for p in munged slurmctld slurmd sbatch squeue sinfo; do
    command -v "$p" >/dev/null 2>&1 || [ -x "/usr/sbin/$p" ] ||
        skip "$p not installed (Debian: slurm-wlm, munge)"
done
PATH=$PATH:/usr/sbin
T=$work/slurm
mkdir -p "$T/state" "$T/spool"
chmod 700 "$work" "$T"
host=$(hostname -s)

stop_daemons() {
    [ -n "${SLURM_CONF:-}" ] && scancel --quiet -u root 2>/dev/null
    for f in slurmd slurmctld munged; do
        [ -s "$T/$f.pid" ] && kill "$(cat "$T/$f.pid")" 2>/dev/null
    done
    for pid in ${ctld_pid:-} ${d_pid:-}; do kill "$pid" 2>/dev/null; done
    # Wait (bounded) so the temporary folder can go.
    for i in 1 2 3 4 5 6 7 8 9 10; do
        alive=0
        for pid in ${ctld_pid:-} ${d_pid:-}; do kill -0 "$pid" 2>/dev/null && alive=1; done
        [ "$alive" -eq 0 ] && break
        sleep 0.5
    done
}
cleanup_hooks="stop_daemons"

# Free TCP ports: the kernel's pick for a listening socket, released.
free_port() {
    python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])'
}
p1=$(free_port)
p2=$(free_port)
[ "$p1" != "$p2" ] || p2=$((p1 + 1))

dd if=/dev/urandom of="$T/munge.key" bs=1024 count=1 2>/dev/null
chmod 400 "$T/munge.key"
munged -f --key-file="$T/munge.key" --socket="$T/munge.sock" --pid-file="$T/munged.pid" \
    --log-file="$T/munged.log" --seed-file="$T/munged.seed" ||
    skip "munged does not start: $(tail -3 "$T/munged.log" 2>/dev/null)"

cat >"$T/slurm.conf" <<CONF
ClusterName=rgltest
SlurmctldHost=$host(127.0.0.1)
SlurmUser=root
SlurmdUser=root
SlurmctldPort=$p1
SlurmdPort=$p2
AuthType=auth/munge
AuthInfo=socket=$T/munge.sock
CredType=cred/munge
StateSaveLocation=$T/state
SlurmdSpoolDir=$T/spool
SlurmctldPidFile=$T/slurmctld.pid
SlurmdPidFile=$T/slurmd.pid
SlurmctldLogFile=$T/slurmctld.log
SlurmdLogFile=$T/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SwitchType=switch/none
MpiDefault=none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=rgl Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$T/slurm.conf
slurmctld -D -f "$SLURM_CONF" >"$T/slurmctld.out" 2>&1 &
ctld_pid=$!
slurmd -D -f "$SLURM_CONF" >"$T/slurmd.out" 2>&1 &
d_pid=$!
up=0
for i in $(seq 1 60); do
    if sinfo -h -o %T 2>/dev/null | grep -q idle; then
        up=1
        break
    fi
    kill -0 "$ctld_pid" 2>/dev/null && kill -0 "$d_pid" 2>/dev/null || break
    sleep 0.5
done
[ "$up" -eq 1 ] || skip "the Slurm daemons did not start: $(tail -3 "$T/slurmctld.log" "$T/slurmd.log" "$T/slurmctld.out" "$T/slurmd.out" 2>/dev/null | tr '\n' ' ')"
echo "one-node cluster up on $host (ports $p1, $p2)"

cd "$work" || exit 1
"$mkanim" anim.raygl 6 80 60 || exit 1
run "$r2p" anim.raygl -o shared --submit
expect_rc 0 "--submit"
cat "$work/out"
grep -q "^Submitted batch job" "$work/out" || fail "sbatch did not submit: $(cat "$work/out")"
[ -x shared/render.slurm ] && grep -q "^#SBATCH --array=0-5$" shared/render.slurm ||
    fail "render.slurm: $(cat shared/render.slurm)"

# Wait for the array (bounded: 120 s).
done_=0
for i in $(seq 1 240); do
    if [ -z "$(squeue -h 2>/dev/null)" ]; then
        done_=1
        break
    fi
    sleep 0.5
done
[ "$done_" -eq 1 ] && ok "the job array finished" || fail "the job array did not finish in 120 s: $(squeue)"
n=$(ls shared/*.png 2>/dev/null | wc -l)
[ "$n" -eq 6 ] && ok "6 PNGs from the cluster" || fail "expected 6 PNGs, found $n; logs: $(cat shared/slurm-*.log 2>/dev/null)"
run "$r2p" anim.raygl -o local --render -q
expect_rc 0 "local render"
m=$(same_pngs local shared)
[ "$m" -eq 6 ] && ok "every cluster PNG matches the local render" || fail "compared $m"

[ "$fails" -eq 0 ] && echo "slurm: all checks passed" || echo "slurm: $fails check(s) failed"
[ "$fails" -eq 0 ]
