"""`ilahrs.cli.dataset.write_capture` as the map step of dask.distributed (a LocalCluster of one
worker): a fleet's captures go to a cluster with no code of ours beyond that function,
and the dataset is the one `ilahrs decode ... --to parquet` writes."""

from __future__ import annotations

import io
import pickle
from contextlib import redirect_stderr
from pathlib import Path

import pytest
from test_parquet import raw_dump, two_way

from ilahrs.cli import main
from ilahrs.cli.dataset import CaptureParts, DatasetOptions, part_name, write_capture

pq = pytest.importorskip("pyarrow.parquet")
distributed = pytest.importorskip("distributed")


def test_write_capture_is_the_map_step_of_dask_distributed(tmp_path: Path) -> None:
    (tmp_path / "fleet" / "unit1").mkdir(parents=True)
    (tmp_path / "fleet" / "unit2").mkdir()
    captures = [tmp_path / "fleet" / "unit1" / "log.pcapng", tmp_path / "fleet" / "unit2" / "log.pcapng"]
    captures[0].write_bytes(two_way())
    captures[1].write_bytes(raw_dump())  # a raw dump, whatever its name says
    paths = [str(c) for c in captures]
    out = tmp_path / "cluster"
    options = DatasetOptions(kinds=("full_output", "PAHR", "damaged"))
    with (
        distributed.LocalCluster(n_workers=1, threads_per_worker=2, processes=False, dashboard_address=None) as cluster,
        distributed.Client(cluster) as client,
    ):
        done: list[CaptureParts] = client.gather(client.map(write_capture, paths, out=str(out), options=options))
    assert [d.capture for d in done] == paths and all(d.error is None for d in done)
    assert done[0].rows == {"full_output": 99, "damaged": 1} and done[1].rows == {"PAHR": 3, "damaged": 1}
    assert sorted(p for d in done for p in d.parts) == sorted(
        f"kind={kind}/{part_name(paths[i])}"
        for i, kind in ((0, "full_output"), (0, "damaged"), (1, "PAHR"), (1, "damaged"))
    )
    cli = tmp_path / "cli"
    with redirect_stderr(io.StringIO()):
        status = main(
            ["decode", *paths, "--to", "parquet", str(cli), "--types", "full_output,PAHR,damaged", "--jobs", "1"]
        )
    assert status == 0
    for part in (p for d in done for p in d.parts):
        assert pq.read_table(out / part).equals(pq.read_table(cli / part)), part
    # A cluster of processes sends the function by reference and its arguments and results pickled
    # (the worker threads of this LocalCluster keep the test cheap: processes take ~9 s to start).
    sent = pickle.loads(pickle.dumps((write_capture, options, done)))
    assert sent == (write_capture, options, done)
    alone = write_capture(paths[1], str(tmp_path / "alone"))  # in this process, every kind
    assert alone.error is None and alone.messages == 7 and alone.damaged == 1
