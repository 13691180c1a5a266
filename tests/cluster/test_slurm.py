"""docs/cluster.md's Slurm job array on a single-node Slurm cluster, against one `inkshade batch`.

The test starts its own cluster in a temporary directory: munged with a fresh key and its own
socket, slurmctld and slurmd in the foreground with SLURM_CONF at a slurm.conf written here
(free ports, state, spool, logs and pid files in the directory; no systemd, no cgroups). It
then runs the Slurm section's two code blocks as they stand (the sbatch script and the commands
that submit it and the completeness check), waits for the queue to drain, and checks: every
task and the check completed with exit 0; each task's log has its shard's summary and the
shards add up to the whole manifest, every job rendered once; the dataset is byte for byte the
one a single `inkshade batch` process writes (metadata without its timings) with every job's
metadata once. The daemons are stopped, and any job left cancelled, however the test ends.

Run by ctest with INKSHADE_BIN at the CLI and INKSHADE_SOURCE_DIR at the source tree; needs
Debian's slurmctld, slurmd, slurm-client and munge (scripts/setup). Runs as root in CI; where
the daemons cannot start, the test fails with their logs.
"""
import ctypes
import json
import os
import pwd
import re
import shutil
import signal
import socket
import subprocess
import tempfile
import time
import unittest

INKSHADE_BIN = os.environ["INKSHADE_BIN"]
DOC = os.path.join(os.environ["INKSHADE_SOURCE_DIR"], "docs", "cluster.md")

# 3 models, 14 jobs: the four shards get 3, 4, 3 and 4 jobs and two of them cut a model in two.
MANIFEST = """model,views,styles,size,format
builtin:torus,0:0;90:30;180:60,"toon,ink-vector",64x64,"png,svg"
builtin:sphere,0:0;90:30,"toon,ink-vector",64x64,"png,svg"
"builtin:torus-knot:segments=96",0:0;90:30,"toon,ink-vector",64x64,"png,svg"
"""
JOBS = 14
SUMMARY = re.compile(r"^batch: (\d+) jobs: (\d+) done, (\d+) skipped, (\d+) failed in ", re.M)

# Bounded waits, together well inside ctest's TIMEOUT (300 s) with the daemons' stop.
DAEMON_START_SECONDS = 30
QUEUE_DRAIN_SECONDS = 120


def doc_blocks():
    """The sbatch script and the submit commands: the first two code blocks of the Slurm section."""
    with open(DOC) as f:
        text = f.read()
    section = text.split("\n## Slurm job array\n", 1)[1].split("\n## ", 1)[0]
    blocks = re.findall(r"^```(\w+)\n(.*?)^```$", section, re.M | re.S)
    assert [lang for lang, _ in blocks[:2]] == ["bash", "sh"], f"{DOC}: Slurm section's blocks: {blocks}"
    return blocks[0][1], blocks[1][1]


def tree(root):
    """{relative path: bytes} of every file under root."""
    files = {}
    for folder, _, names in os.walk(root):
        for name in names:
            path = os.path.join(folder, name)
            with open(path, "rb") as f:
                files[os.path.relpath(path, root)] = f.read()
    return files


def without_timings(metadata):
    doc = json.loads(metadata)
    doc.pop("timings_ms")  # the one field that differs between two runs of a job
    return doc


def free_ports(count):
    """Ports nothing listens on now: bound together so they differ, then released for Slurm."""
    sockets = [socket.socket() for _ in range(count)]
    try:
        for s in sockets:
            s.bind(("127.0.0.1", 0))
        return [s.getsockname()[1] for s in sockets]
    finally:
        for s in sockets:
            s.close()


def program(name):
    """A daemon or client by name; the daemons are in /usr/sbin, which a user's PATH may lack."""
    found = shutil.which(name, path=os.environ.get("PATH", "") + ":/usr/sbin:/sbin")
    if not found:
        raise AssertionError(f"{name} not found: install Debian's slurmctld, slurmd, slurm-client and munge "
                             "(scripts/setup)")
    return found


def terminate_with_parent():
    """In the child before exec: SIGTERM when the test's process ends, however it ends."""
    PR_SET_PDEATHSIG = 1
    ctypes.CDLL(None, use_errno=True).prctl(PR_SET_PDEATHSIG, signal.SIGTERM)


def tail(path, lines=40):
    try:
        with open(path, errors="replace") as f:
            return "".join(f.readlines()[-lines:])
    except OSError as e:
        return f"({e.strerror})\n"


def jobs_of(scontrol_output):
    """`scontrol show job -o`: one dict a job (an array task is a job of its own)."""
    return [dict(re.findall(r"(\w+)=(\S*)", line)) for line in scontrol_output.splitlines() if line.strip()]


class SlurmCluster:
    """munged, slurmctld and slurmd of one node, everything in `root`, started and stopped here."""

    def __init__(self, root):
        self.root = root
        self.processes = []  # (name, Popen), in start order
        self.munge_dir = os.path.join(root, "munge")  # key and seed: the owner's only
        self.run_dir = os.path.join(root, "run")  # socket and pid files: searchable by all
        self.socket = os.path.join(self.run_dir, "munge.socket")
        self.conf = os.path.join(root, "slurm.conf")
        self.env = dict(os.environ, SLURM_CONF=self.conf)
        self.node = socket.gethostname().split(".")[0]  # slurmctld checks it runs on SlurmctldHost

    def logs(self):
        # munged in the foreground logs to its output, not to a file.
        names = ["munged.out", "slurmctld.log", "slurmd.log", "slurmctld.out", "slurmd.out"]
        paths = [os.path.join(self.root, n) for n in names]
        return "".join(f"--- {p} (last lines)\n{tail(p)}" for p in paths)

    def fail(self, message):
        user = pwd.getpwuid(os.getuid()).pw_name
        raise AssertionError(f"{message} (Slurm as user {user}, in {self.root})\n{self.logs()}")

    def spawn(self, name, argv):
        out = open(os.path.join(self.root, name + ".out"), "w")
        # A session of its own: the daemons do not get the terminal's signals, the test stops them
        # (scancel first); and SIGTERM if the test itself dies (killed by ctest's timeout).
        p = subprocess.Popen(argv, env=self.env, stdout=out, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
                             start_new_session=True, preexec_fn=terminate_with_parent)
        out.close()
        self.processes.append((name, p))
        return p

    def wait_for(self, what, ready, seconds):
        deadline = time.monotonic() + seconds
        while time.monotonic() < deadline:
            if ready():
                return
            for name, p in self.processes:
                if p.poll() is not None:
                    self.fail(f"{name} exited with {p.returncode} while waiting for {what}")
            time.sleep(0.2)
        self.fail(f"no {what} after {seconds} s")

    def client(self, *argv, check=True):
        r = subprocess.run([program(argv[0]), *argv[1:]], env=self.env, capture_output=True, text=True, timeout=60)
        if check and r.returncode != 0:
            self.fail(f"{' '.join(argv)} exited with {r.returncode}: {r.stderr.strip()}")
        return r

    def start(self):
        os.mkdir(self.munge_dir, 0o700)
        os.mkdir(self.run_dir, 0o755)
        key = os.path.join(self.munge_dir, "munge.key")
        with open(os.open(key, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600), "wb") as f:
            f.write(os.urandom(128))  # a key of this cluster only
        self.spawn("munged", [program("munged"), "--foreground", "--key-file", key, "--socket", self.socket,
                              "--pid-file", os.path.join(self.run_dir, "munged.pid"),
                              "--seed-file", os.path.join(self.munge_dir, "munged.seed")])
        self.wait_for("munged socket", lambda: os.path.exists(self.socket), DAEMON_START_SECONDS)

        for d in ("state", "spool"):
            os.mkdir(os.path.join(self.root, d), 0o755)
        ctld_port, slurmd_port = free_ports(2)
        user = pwd.getpwuid(os.getuid()).pw_name
        # The node claims 16 CPUs and 32 GiB whatever the machine has (config_overrides, meant
        # for tests), so the docs' script is submitted as written: 4 tasks x 4 CPUs x 8 GiB.
        # Nothing enforces the requests without cgroups: the four tasks share this machine's cores.
        conf = f"""ClusterName=inkshade-test
SlurmctldHost={self.node}(127.0.0.1)
SlurmctldPort={ctld_port}
SlurmdPort={slurmd_port}
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket={self.socket}
SlurmUser={user}
SlurmdUser={user}
StateSaveLocation={self.root}/state
SlurmdSpoolDir={self.root}/spool
SlurmctldPidFile={self.run_dir}/slurmctld.pid
SlurmdPidFile={self.run_dir}/slurmd.pid
SlurmctldLogFile={self.root}/slurmctld.log
SlurmdLogFile={self.root}/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MpiDefault=none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SchedulerType=sched/builtin
ReturnToService=2
MinJobAge=600
MailProg=/bin/true
SlurmdParameters=config_overrides
NodeName={self.node} NodeAddr=127.0.0.1 CPUs=16 RealMemory=32768 State=UNKNOWN
PartitionName=test Nodes={self.node} Default=YES MaxTime=INFINITE State=UP
"""
        with open(self.conf, "w") as f:
            f.write(conf)
        self.spawn("slurmctld", [program("slurmctld"), "-D"])
        self.spawn("slurmd", [program("slurmd"), "-D", "-N", self.node])
        self.wait_for("idle node in sinfo",
                      lambda: self.client("sinfo", "-h", "-N", "-o", "%t", check=False).stdout.strip() == "idle",
                      DAEMON_START_SECONDS)

    def queue(self):
        r = self.client("squeue", "-h", "-o", "%i %T", check=False)
        return r.stdout.strip() if r.returncode == 0 else "(squeue failed)"

    def wait_until_queue_empty(self, seconds):
        self.wait_for("empty queue", lambda: self.queue() == "", seconds)

    def stop(self):
        """Cancels what is left (a failed test's jobs), then stops slurmd, slurmctld, munged."""
        if any(name == "slurmctld" and p.poll() is None for name, p in self.processes):
            self.client("scancel", "--user", pwd.getpwuid(os.getuid()).pw_name, check=False)
            deadline = time.monotonic() + 20
            while self.queue() not in ("", "(squeue failed)") and time.monotonic() < deadline:
                time.sleep(0.2)
        for name, p in reversed(self.processes):
            if p.poll() is None:
                p.send_signal(signal.SIGTERM)
                try:
                    p.wait(timeout=20)
                except subprocess.TimeoutExpired:
                    p.kill()
                    p.wait()
        self.processes = []


class SlurmJobArrayTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory(prefix="inkshade-slurm-")
        cls.addClassCleanup(cls.tmp.cleanup)
        root = cls.tmp.name
        os.chmod(root, 0o755)  # munged: every directory above its socket must be searchable by all
        # The shared directory of the docs: jobs.csv in, dataset/ and logs/ out; inkshade on the PATH.
        cls.work = os.path.join(root, "shared")
        os.mkdir(cls.work)
        with open(os.path.join(cls.work, "jobs.csv"), "w") as f:
            f.write(MANIFEST)
        bin_dir = os.path.join(root, "bin")
        os.mkdir(bin_dir)
        os.symlink(INKSHADE_BIN, os.path.join(bin_dir, "inkshade"))
        os.environ["PATH"] = bin_dir + os.pathsep + os.environ["PATH"]

        dry = subprocess.run(["inkshade", "batch", "jobs.csv", "-o", "dry", "--dry-run"], cwd=cls.work,
                             capture_output=True, text=True, check=True)
        cls.stems = [line.split("\t")[0] for line in dry.stdout.splitlines()]
        assert len(cls.stems) == JOBS, dry.stdout
        one = os.path.join(root, "one")
        subprocess.run(["inkshade", "batch", "jobs.csv", "-o", one, "--quiet"], cwd=cls.work, capture_output=True,
                       text=True, check=True)
        cls.expected = tree(one)

        cls.cluster = SlurmCluster(os.path.join(root, "cluster"))
        os.mkdir(cls.cluster.root)
        cls.addClassCleanup(cls.cluster.stop)
        cls.cluster.start()

    def diagnostics(self):
        logs = os.path.join(self.work, "logs")
        job_logs = sorted(os.listdir(logs)) if os.path.isdir(logs) else []
        text = "".join(f"--- {name}\n{tail(os.path.join(logs, name))}" for name in job_logs)
        jobs = self.cluster.client("scontrol", "show", "job", "-o", check=False).stdout
        return f"\n--- scontrol show job -o\n{jobs}{text}{self.cluster.logs()}"

    def test_job_array_of_the_docs_writes_what_one_batch_process_writes(self):
        script, submit = doc_blocks()
        self.assertIn("#SBATCH --array=0-3", script)
        self.assertIn('--shard "$((SLURM_ARRAY_TASK_ID + 1))/4"', script)
        with open(os.path.join(self.work, "render-dataset.sbatch"), "w") as f:
            f.write(script)
        r = subprocess.run(["bash", "-euo", "pipefail", "-c", submit], cwd=self.work, env=self.cluster.env,
                           capture_output=True, text=True, timeout=60)
        self.assertEqual(r.returncode, 0, f"the submit commands: {r.stderr}{self.diagnostics()}")
        check_id = r.stdout.strip()
        self.assertRegex(check_id, r"^\d+$", r.stdout)
        try:
            self.cluster.wait_until_queue_empty(QUEUE_DRAIN_SECONDS)
            self.check_results(check_id)
        except AssertionError as e:
            raise AssertionError(f"{e}{self.diagnostics()}") from None

    def check_results(self, check_id):
        jobs = jobs_of(self.cluster.client("scontrol", "show", "job", "-o").stdout)
        tasks = sorted((j for j in jobs if j.get("ArrayTaskId")), key=lambda j: int(j["ArrayTaskId"]))
        check = [j for j in jobs if j["JobId"] == check_id]
        self.assertEqual([j["ArrayTaskId"] for j in tasks], ["0", "1", "2", "3"], "one array of four tasks")
        self.assertEqual(len({j["ArrayJobId"] for j in tasks}), 1)
        self.assertEqual(len(check), 1, "the completeness check")
        self.assertEqual(len(jobs), 5, "four tasks and the check, nothing else")
        for j in tasks + check:
            self.assertEqual((j["JobState"], j["ExitCode"]), ("COMPLETED", "0:0"), f"job {j['JobId']}")
        self.assertEqual(tasks[0]["JobName"], "inkshade-dataset")

        # Each task's log: its shard's summary, everything rendered, nothing skipped or failed;
        # together the whole manifest, so no job was rendered by two tasks.
        array_id = tasks[0]["ArrayJobId"]
        totals = []
        for k in range(4):
            with open(os.path.join(self.work, "logs", f"inkshade-{array_id}_{k}.log")) as f:
                log = f.read()
            summaries = SUMMARY.findall(log)
            self.assertEqual(len(summaries), 1, f"task {k}: {log!r}")
            total, done, skipped, failed = map(int, summaries[0])
            self.assertGreater(total, 0, f"task {k}")
            self.assertEqual((done, skipped, failed), (total, 0, 0), f"task {k}: {log!r}")
            totals.append(total)
        self.assertEqual(sum(totals), JOBS, f"shard sizes {totals}")
        with open(os.path.join(self.work, "logs", f"inkshade-check-{check_id}.log")) as f:
            log = f.read()
        self.assertEqual([tuple(map(int, s)) for s in SUMMARY.findall(log)], [(JOBS, 0, JOBS, 0)], log)

        # The union of the four tasks' files is what one process writes, byte for byte.
        actual = tree(os.path.join(self.work, "dataset"))
        self.assertEqual(sorted(actual), sorted(self.expected))
        for path, data in self.expected.items():
            with self.subTest(path=path):
                if path.endswith(".json"):
                    self.assertEqual(without_timings(actual[path]), without_timings(data))
                else:
                    self.assertEqual(actual[path], data)  # PNG and SVG bytes
        stems = [json.loads(data)["stem"] for path, data in actual.items() if path.endswith(".json")]
        self.assertEqual(sorted(stems), sorted(self.stems), "every job's metadata once")


if __name__ == "__main__":
    unittest.main()
