"""Studies on a real Slurm (quicksand/slurm.py): a controller and one node daemon started here, with
their own munge, on this machine, and stopped at the end (Debian's slurmctld, slurmd, slurm-client
and munge: tools/setup.sh). Skipped, saying why, where they are missing or the tests do not run as
root (the daemons and their jobs run as root here, as CI does)."""
import os
import shutil
import signal
import socket
import subprocess
import sys
import time

import pytest

REPOSITORY = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
STUDY_PY = os.path.join(REPOSITORY, "tools", "study.py")
NEEDED = ["munged", "slurmctld", "slurmd", "sbatch", "squeue", "scancel", "scontrol"]

missing = [c for c in NEEDED if not shutil.which(c)]
if missing:
    pytest.skip(f"no Slurm here ({', '.join(missing)} missing: bash tools/setup.sh installs them)",
                allow_module_level=True)
if os.geteuid() != 0:
    pytest.skip("the Slurm tests start slurmd, which runs as root", allow_module_level=True)


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def wait_for(condition, seconds, what):
    end = time.time() + seconds
    while time.time() < end:
        if condition():
            return
        time.sleep(0.2)
    raise AssertionError(f"timed out after {seconds} s waiting for {what}")


@pytest.fixture(scope="module")
def cluster(tmp_path_factory):
    """A one-node Slurm: munged, slurmctld and slurmd on free ports; yields the environment that
    points Slurm's commands at it. Everything started is stopped, also when a daemon fails."""
    if not os.path.ismount("/sys/fs/cgroup"):
        pytest.skip("no cgroup filesystem at /sys/fs/cgroup, which Slurm 22.05's slurmd needs to start (a chroot "
                    "without /sys, as tools' fresh-machine check is)")
    root = tmp_path_factory.mktemp("slurm")
    for d in ("state", "spool"):
        (root / d).mkdir()
    key = root / "munge.key"
    key.write_bytes(os.urandom(1024))
    key.chmod(0o400)
    socket_path = root / "munge.socket"
    started = []
    try:
        yield from _cluster(root, key, socket_path, started)
    finally:
        env = dict(os.environ, SLURM_CONF=str(root / "slurm.conf"))
        if "slurmctld" in started:
            subprocess.run(["scancel", "--user=root"], env=env, capture_output=True)
        for pid_file in ("slurmd.pid", "slurmctld.pid"):
            try:
                os.kill(int((root / pid_file).read_text()), signal.SIGTERM)
            except (OSError, ValueError):
                pass
        time.sleep(1)
        if "munged" in started:
            subprocess.run(["munged", "-s", "-S", str(socket_path)], capture_output=True)


def _cluster(root, key, socket_path, started):
    subprocess.run(["munged", "--force", "-S", str(socket_path), f"--key-file={key}", f"--log-file={root}/munged.log",
                    f"--pid-file={root}/munged.pid", f"--seed-file={root}/munged.seed"], check=True)
    started.append("munged")
    host = socket.gethostname().split(".")[0]
    memory = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES") // 2**20 // 2
    cores = os.cpu_count() or 1
    conf = root / "slurm.conf"
    conf.write_text(f"""ClusterName=quicksandtest
SlurmctldHost={host}(127.0.0.1)
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket={socket_path}
CredType=cred/munge
StateSaveLocation={root}/state
SlurmdSpoolDir={root}/spool
SlurmctldPidFile={root}/slurmctld.pid
SlurmdPidFile={root}/slurmd.pid
SlurmctldPort={free_port()}
SlurmdPort={free_port()}
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/filetxt
JobCompLoc={root}/jobcomp.txt
MinJobAge=600
KillWait=10
MpiDefault=none
ReturnToService=2
SlurmctldLogFile={root}/slurmctld.log
SlurmdLogFile={root}/slurmd.log
NodeName={host} NodeAddr=127.0.0.1 CPUs={cores} RealMemory={memory} State=UNKNOWN
PartitionName=debug Nodes={host} Default=YES MaxTime=INFINITE State=UP
""")
    env = dict(os.environ, SLURM_CONF=str(conf))
    for daemon in ("slurmctld", "slurmd"):
        done = subprocess.run([daemon, "-f", str(conf)], env=env, capture_output=True, text=True)
        if done.returncode != 0:
            log = (root / f"{daemon}.log").read_text() if (root / f"{daemon}.log").exists() else ""
            raise AssertionError(f"{daemon} did not start ({done.returncode}): {done.stderr}\n{log[-1500:]}")
        started.append(daemon)
    wait_for(lambda: "idle" in subprocess.run(["sinfo", "--noheader", "-o", "%t"], capture_output=True, text=True,
                                              env=env).stdout, 30, "the node to be idle")
    yield {"env": env, "root": root}


def make_study(folder, end):
    """The reservoirSize study's first parameter, two values, `end` s each (tools/tests: short)."""
    folder.mkdir(parents=True)
    base = os.path.relpath(os.path.join(REPOSITORY, "cases", "deltaresColumnLumped"), folder)
    (folder / "study.toml").write_text(f'''base = "{base}"
parallel = 2
threads = 1
progress_interval = 1.0
[parameters]
"reservoir.area" = [0.0083, 0.0166]
[set]
"time.end" = {end}
"output.fields" = false
"output.progress_interval" = 0.2
''')
    return str(folder / "study.toml")


def study(path, env, *options, timeout=600):
    return subprocess.run([sys.executable, STUDY_PY, path, "--no-plots", *options], capture_output=True, text=True,
                          env=env, timeout=timeout)


def table(path):
    return open(os.path.join(os.path.dirname(path), "output", "study.csv")).read()


@pytest.fixture(scope="module")
def local_table(tmp_path_factory):
    path = make_study(tmp_path_factory.mktemp("local") / "study", 4.0)
    done = study(path, os.environ)
    assert done.returncode == 0, done.stderr
    return table(path)


def test_the_job_array_gives_the_local_study_csv(cluster, local_table, tmp_path):
    path = make_study(tmp_path / "study", 4.0)
    done = study(path, cluster["env"], "--scheduler", "slurm")
    assert done.returncode == 0, done.stdout + done.stderr
    assert "submitted job array" in done.stdout
    assert table(path) == local_table  # to the last digit
    script = open(tmp_path / "study" / "output" / "slurm" / "array.sh").read()
    assert "#SBATCH --array=0-1%2" in script and "#SBATCH --cpus-per-task=1" in script and "#SBATCH --mem=" in script


def test_ctrl_c_cancels_the_array_and_the_same_command_resumes(cluster, local_table, tmp_path):
    path = make_study(tmp_path / "study", 4.0)  # 3.4 s a run: progress lines every 0.2 s
    logs = tmp_path / "study" / "output"
    driver = subprocess.Popen([sys.executable, STUDY_PY, path, "--no-plots", "--scheduler", "slurm"],
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=cluster["env"])
    # once a run has said how far it is, Ctrl-C
    wait_for(lambda: any("%)" in p.read_text() for p in logs.glob("*.log")) if logs.exists() else False, 120,
             "a variant's first progress line")
    driver.send_signal(signal.SIGINT)
    out, err = driver.communicate(timeout=120)
    assert driver.returncode == 130, out + err
    assert "resume" in err
    queued = subprocess.run(["squeue", "--noheader"], capture_output=True, text=True, env=cluster["env"]).stdout
    assert queued.strip() == "", f"tasks left on Slurm: {queued}"
    done = study(path, cluster["env"], "--scheduler", "slurm")
    assert done.returncode == 0, done.stdout + done.stderr
    assert table(path) == local_table


def test_a_task_slurm_kills_is_reported_and_resumed(cluster, local_table, tmp_path):
    path = make_study(tmp_path / "study", 4.0)
    logs = tmp_path / "study" / "output"
    driver = subprocess.Popen([sys.executable, STUDY_PY, path, "--no-plots", "--scheduler", "slurm"],
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=cluster["env"])
    wait_for(lambda: any("%)" in p.read_text() for p in logs.glob("01_*.log")) if logs.exists() else False, 120,
             "the first variant's first progress line")
    job = subprocess.run(["squeue", "--noheader", "--array", "--format=%F"], capture_output=True, text=True,
                         env=cluster["env"]).stdout.split()[0]  # the array's job id
    subprocess.run(["scancel", f"{job}_0"], env=cluster["env"], check=True)  # as a time limit would
    out, err = driver.communicate(timeout=300)
    assert driver.returncode == 1, out + err  # a variant did not finish
    rows = table(path).splitlines()
    first = next(r for r in rows if r.startswith("01_"))
    assert ",killed," in first and "Slurm ended task" in first and "CANCELLED" in first, first
    done = study(path, cluster["env"], "--scheduler", "slurm")
    assert done.returncode == 0, done.stdout + done.stderr
    assert table(path) == local_table  # resumed from its checkpoint, bit for bit


def test_a_slurm_that_is_not_running_is_a_clear_error(cluster, tmp_path):
    path = make_study(tmp_path / "study", 4.0)
    conf = tmp_path / "slurm.conf"
    text = open(cluster["env"]["SLURM_CONF"]).read()
    port = free_port()
    conf.write_text("\n".join(f"SlurmctldPort={port}" if line.startswith("SlurmctldPort=") else line
                              for line in text.splitlines()) + "\n")
    env = dict(cluster["env"], SLURM_CONF=str(conf))
    done = study(path, env, "--scheduler", "slurm", timeout=120)
    assert done.returncode == 1
    assert "--scheduler slurm: submitting the job array failed" in done.stderr
    assert "Unable to contact slurm controller" in done.stderr
    assert not os.path.exists(os.path.join(tmp_path, "study", "output", "study.csv"))


def test_a_variant_failing_on_the_cluster_is_reported_with_its_own_error(cluster, tmp_path):
    # tests/study/test_StudyRuns.cpp's failing variant: the second flux lifts the bed to the
    # overflow, where "stop" ends the run with quicksand's error
    folder = tmp_path / "study"
    folder.mkdir()
    base = os.path.join(REPOSITORY, "cases", "verification", "bed_expansion")
    (folder / "study.toml").write_text(f'base = "{base}"\nthreads = 1\ncombine = "zip"\n[parameters]\n'
                                       '"gate.flux" = [1.380e-3, 2.0e-2]\n"column.sand_overflow" = ["stop", "stop"]\n'
                                       '[set]\n"output.fields" = false\n"time.end" = 6.0\n')
    done = study(str(folder / "study.toml"), cluster["env"], "--scheduler", "slurm")
    assert done.returncode == 1, done.stdout + done.stderr
    assert "did not finish" in done.stderr
    rows = table(str(folder / "study.toml")).splitlines()
    assert ",finished," in rows[1]
    assert ",failed," in rows[2] and "overflow" in rows[2], rows[2]


def test_a_variant_its_check_refuses_stops_the_study_before_anything_is_submitted(cluster, tmp_path):
    folder = tmp_path / "study"
    folder.mkdir()
    base = os.path.join(REPOSITORY, "cases", "deltaresColumnLumped")
    (folder / "study.toml").write_text(f'base = "{base}"\n[parameters]\n"reservoir.area" = [0.0083, -1.0]\n')
    done = study(str(folder / "study.toml"), cluster["env"], "--scheduler", "slurm")
    assert done.returncode == 1
    assert "1 of 2 variants fail their check" in done.stderr and "reservoir.area" in done.stderr
    assert not (folder / "output" / "slurm").exists()
    queued = subprocess.run(["squeue", "--noheader"], capture_output=True, text=True, env=cluster["env"]).stdout
    assert queued.strip() == ""
