"""A batch manifest mapped over a Dask cluster (``dask.distributed``; docs/cluster.md).

Each task renders one shard, ``inkshade.batch(..., shard=(k, n))``: the same contiguous blocks
of the canonical job list as ``inkshade batch --shard K/N``, so the union of the shards is what
one ``inkshade batch`` writes, byte for byte. Tasks share nothing but the output directory;
each job's files are written atomically and a shard run again skips its complete jobs, so a
task that Dask reruns (its worker died) only renders what is missing.

    from dask.distributed import Client
    import inkshade.dask
    summary = inkshade.dask.batch(Client("tcp://scheduler:8786"), "/shared/dataset",
                                  manifest="/shared/jobs.csv", shards=64)
"""
import os
import socket
import time

import inkshade

__all__ = ["batch", "run_shard"]


def run_shard(output_dir, shard, options):
    """One task: shard (k, n) of the batch, in the worker's process. Returns its summary."""
    summary = inkshade.batch(output_dir, shard=tuple(shard), **options)
    summary.update(shard=list(shard), host=socket.gethostname(), pid=os.getpid())  # who rendered it
    return summary


def batch(client, output_dir, *, manifest=None, models=None, shards=None, retries=0, **options):
    """Renders a dataset as ``inkshade.batch`` does, in ``shards`` Dask tasks.

    client: a ``distributed.Client`` (None: the current default client). output_dir, manifest
    and models must be reachable from every worker (a shared file system); relative paths are
    made absolute here, relative model paths inside a manifest are resolved by each worker
    from its own working directory. shards: the number of tasks (default: the cluster's
    threads); more shards than workers balance uneven jobs. retries: Dask's retries of a task
    that raised. Every other keyword (views, styles, size, formats, force, samples, lights,
    margin, aov) is ``inkshade.batch``'s. Returns the summed summary {total, done, skipped,
    failed, seconds (wall clock), failures} with ``shards``, each task's own summary.
    """
    if client is None:
        from distributed import default_client

        client = default_client()
    if (manifest is None) == (models is None):
        raise ValueError("batch: give exactly one of manifest= or models=")
    if "shard" in options or "progress" in options:
        raise ValueError("batch: shard= and progress= are chosen per task by inkshade.dask")
    if manifest is not None:
        options["manifest"] = os.path.abspath(manifest)
    else:
        options["models"] = os.path.abspath(models)
    if shards is None:
        shards = max(1, sum(client.nthreads().values()))
    if not isinstance(shards, int) or shards < 1:
        raise ValueError(f"shards: expected a positive integer, got {shards!r}")
    output_dir = os.path.abspath(output_dir)

    start = time.monotonic()
    # pure=False: calling batch again (to resume or re-render) submits new tasks, never
    # returns the results Dask may still hold for identical arguments.
    futures = [
        client.submit(run_shard, output_dir, (k, shards), options, pure=False, retries=retries,
                      key=f"inkshade-shard-{k}-of-{shards}-{os.urandom(4).hex()}")
        for k in range(1, shards + 1)
    ]
    results = client.gather(futures)
    summary = {key: sum(r[key] for r in results) for key in ("total", "done", "skipped", "failed")}
    summary["seconds"] = time.monotonic() - start
    summary["failures"] = [f for r in results for f in r["failures"]]
    summary["shards"] = results
    return summary
