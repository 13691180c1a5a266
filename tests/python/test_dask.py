"""inkshade.dask on dask.distributed against one `inkshade batch` process: the same files, byte
for byte, and every job's metadata once. Two clusters: a LocalCluster of two worker processes,
and the commands of docs/cluster.md (dask-scheduler, two dask-worker processes).

Run by ctest with PYTHONPATH at the build tree's package (the spawned workers inherit it) and
INKSHADE_BIN at the CLI; needs Debian's python3-distributed (scripts/setup).
"""
import json
import os
import shutil
import signal
import subprocess
import tempfile
import time
import unittest

from distributed import Client, LocalCluster

import inkshade
import inkshade.dask

INKSHADE_BIN = os.environ["INKSHADE_BIN"]

# 3 models x 2 views x 2 styles = 12 jobs, PNG and SVG, and a model that fails.
MANIFEST = """model,views,styles,size,format
builtin:torus,0:0;90:30,"lambert,ink-vector",48x32,"png,svg"
builtin:sphere,0:0;90:30,"lambert,ink-vector",48x32,"png,svg"
"builtin:torus-knot:segments=96",0:0;90:30,"lambert,ink-vector",48x32,"png,svg"
missing-model.obj,0:0,lambert,48x32,png
"""


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


class DaskTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.manifest = os.path.join(cls.tmp.name, "jobs.csv")  # absolute, as inkshade.dask passes it
        with open(cls.manifest, "w") as f:
            f.write(MANIFEST)
        dry = subprocess.run([INKSHADE_BIN, "batch", cls.manifest, "-o", os.path.join(cls.tmp.name, "dry"),
                              "--dry-run"], capture_output=True, text=True, check=True)
        cls.stems = [line.split("\t")[0] for line in dry.stdout.splitlines() if "missing-model" not in line]
        assert len(cls.stems) == 12, dry.stdout
        one = subprocess.run([INKSHADE_BIN, "batch", cls.manifest, "-o", os.path.join(cls.tmp.name, "one"),
                              "--quiet"], capture_output=True, text=True)
        assert one.returncode == 1, one.stderr  # the missing model
        cls.expected = tree(os.path.join(cls.tmp.name, "one"))

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def assert_same_dataset(self, out, summary):
        self.assertEqual((summary["total"], summary["done"], summary["skipped"], summary["failed"]),
                         (13, 12, 0, 1))
        self.assertEqual([f["model"] for f in summary["failures"]], ["missing-model.obj"])
        self.assertEqual(sum(s["total"] for s in summary["shards"]), 13)
        workers = {s["pid"] for s in summary["shards"]}
        self.assertEqual(len(workers), 2, "the shards ran in both worker processes")
        self.assertNotIn(os.getpid(), workers)
        actual = tree(out)
        self.assertEqual(sorted(actual), sorted(self.expected))
        for path, data in self.expected.items():
            with self.subTest(path=path):
                if path.endswith(".json"):
                    self.assertEqual(without_timings(actual[path]), without_timings(data))
                else:
                    self.assertEqual(actual[path], data)  # PNG and SVG bytes
        stems = [json.loads(data)["stem"] for path, data in actual.items() if path.endswith(".json")]
        self.assertEqual(sorted(stems), sorted(self.stems), "every job's metadata once")

    def test_local_cluster_writes_what_one_batch_process_writes(self):
        out = os.path.join(self.tmp.name, "local")
        with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None,
                          local_directory=os.path.join(self.tmp.name, "dask-local")) as cluster, \
                Client(cluster) as client:
            client.wait_for_workers(2)
            summary = inkshade.dask.batch(client, out, manifest=self.manifest, shards=4)
            # Again: every shard skips its complete jobs; the failed one is tried again.
            again = inkshade.dask.batch(client, out, manifest=self.manifest, shards=3)
        self.assertEqual(sorted(s["shard"][0] for s in summary["shards"]), [1, 2, 3, 4])
        self.assert_same_dataset(out, summary)
        self.assertEqual((again["total"], again["done"], again["skipped"], again["failed"]), (13, 0, 12, 1))

    def test_scheduler_and_worker_commands_of_the_docs(self):
        """docs/cluster.md's dask-scheduler and dask-worker, as on a multi-node cluster."""
        scheduler_file = os.path.join(self.tmp.name, "scheduler.json")
        env = dict(os.environ, MESA_SHADER_CACHE_DISABLE="true")
        log = open(os.path.join(self.tmp.name, "dask.log"), "w")
        processes = [subprocess.Popen([shutil.which("dask-scheduler"), "--port", "0", "--no-dashboard",
                                       "--scheduler-file", scheduler_file], env=env, stdout=log, stderr=log,
                                      start_new_session=True)]
        try:
            deadline = time.monotonic() + 60
            while not os.path.exists(scheduler_file) and time.monotonic() < deadline:
                time.sleep(0.1)
            for i in range(2):  # two "nodes"
                processes.append(subprocess.Popen(
                    [shutil.which("dask-worker"), "--scheduler-file", scheduler_file, "--nworkers", "1",
                     "--nthreads", "1", "--no-dashboard", "--local-directory",
                     os.path.join(self.tmp.name, f"dask-{i}")], env=env, stdout=log, stderr=log,
                    start_new_session=True))
            out = os.path.join(self.tmp.name, "commands")
            with Client(scheduler_file=scheduler_file, timeout=60) as client:
                client.wait_for_workers(2, timeout=60)
                summary = inkshade.dask.batch(client, out, manifest=self.manifest)  # a shard per worker
            self.assertEqual(len(summary["shards"]), 2)
            self.assert_same_dataset(out, summary)
        finally:
            # Each command's own process group (a worker's nanny and its worker process), killed:
            # a graceful close takes seconds and the results are already checked.
            for p in processes:
                os.killpg(p.pid, signal.SIGKILL)
                p.wait()
            log.close()

    def test_bad_arguments_fail_before_any_task(self):
        with self.assertRaisesRegex(ValueError, "exactly one of"):
            inkshade.dask.batch(object(), "/tmp/x")
        with self.assertRaisesRegex(ValueError, "chosen per task"):
            inkshade.dask.batch(object(), "/tmp/x", manifest="jobs.csv", shard=(1, 2))
        with self.assertRaisesRegex(ValueError, "shards: expected a positive integer"):
            inkshade.dask.batch(object(), "/tmp/x", manifest="jobs.csv", shards=0)


if __name__ == "__main__":
    unittest.main()
