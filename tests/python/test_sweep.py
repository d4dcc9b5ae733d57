"""sweep(): ensembles on Dask, the same table whatever ran them, and particle-sim's numbers."""

import json
import os
import subprocess

import numpy as np
import pytest

import particle_sandbox as ps
from particle_sandbox import _core
from conftest import GAS

dask = pytest.importorskip("dask.distributed")


@pytest.fixture(scope="module")
def client():
    with dask.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                           dashboard_address=None) as cluster, dask.Client(cluster) as c:
        yield c


def test_a_sweep_has_a_row_per_combination_in_product_order(client, gas):
    table = ps.sweep(gas, seeds=[1, 2], params={"world.restitution": [1.0, 0.9]}, duration=0.5,
                     client=client)
    assert list(table["seed"]) == [1, 1, 2, 2]
    assert list(table["world.restitution"]) == [1.0, 0.9, 1.0, 0.9]
    for column in ("temperature", "temperature_error", "pressure_virial",
                   "pressure_virial_error", "collision_rate"):
        assert column in table.columns
    assert (table["temperature"] > 0).all()
    # Inelastic collisions cool the gas; another seed is another gas.
    assert table["temperature"][1] < table["temperature"][0]
    assert table["temperature"][0] != table["temperature"][2]


def test_the_table_is_the_same_whatever_ran_it(client, gas):
    on_cluster = ps.sweep(gas, seeds=[3, 4], duration=0.5, warmup=0.1, client=client)
    text, source = gas.file_text, gas.source
    in_process = [_core._run_scene(text, source, [], 0.5, 0.1, seed) for seed in (3, 4)]
    for k, row in enumerate(in_process):
        for name, value in row.items():
            got = on_cluster[name][k]
            assert got == value or (np.isnan(got) and np.isnan(value)), name


def test_the_default_local_cluster_gives_the_same_table_as_worker_processes(client, gas):
    params = {"world.restitution": [1.0, 0.8]}
    here = ps.sweep(gas, seeds=[6], params=params, duration=0.3)
    there = ps.sweep(gas, seeds=[6], params=params, duration=0.3, client=client)
    assert here.equals(there)


def test_a_run_measures_what_particle_sim_reports(tmp_path, gas):
    sim = os.environ.get("PSB_SIM")
    if not sim:
        pytest.skip("PSB_SIM (the particle-sim to compare with) is not set")
    path = tmp_path / "gas.json"
    path.write_text(GAS)
    report = json.loads(subprocess.run(
        [sim, str(path), "--seed", "5", "--set", "world.restitution=0.95", "--duration", "2",
         "--warmup", "0.1", "--observables"], check=True, capture_output=True, text=True).stdout)
    row = _core._run_scene(GAS, str(path), [("world.restitution", "0.95")], 2.0, 0.1, 5)
    for name in ("temperature", "pressure_virial", "collision_rate", "wall_collision_rate"):
        assert row[name] == report["observables"][name]["value"], name
        assert row[name + "_error"] == report["observables"][name]["error"], name
    assert row["steps"] == report["steps"]


def test_seeds_on_a_scene_changed_since_it_was_read_are_refused(gas):
    gas.world.restitution = 0.5
    with pytest.raises(ValueError, match="changed after it was read"):
        ps.sweep(gas, seeds=[1], duration=0.1, client=object())
    with pytest.raises(ValueError, match="changed after it was read"):
        ps.sweep(gas, params={"generate.count": [50]}, duration=0.1, client=object())


def test_generate_parameters_apply_to_the_file_generate_block(client, gas):
    table = ps.sweep(gas, params={"generate.count": [50, 80]}, duration=0.2, client=client)
    assert list(table["particles"]) == [50, 80]


def test_a_changed_scene_is_swept_as_it_is(client, gas):
    gas.world.restitution = 0.5
    table = ps.sweep(gas, params={"world.friction": [0.0]}, duration=0.5, client=client)
    unchanged = ps.sweep(ps.parse_scene(gas.file_text, "gas.json"),
                         params={"world.friction": [0.0]}, duration=0.5, client=client)
    assert table["temperature"][0] < unchanged["temperature"][0]  # e = 0.5 cools it


def test_params_must_be_lists(gas):
    with pytest.raises(ValueError, match="list of values"):
        ps.sweep(gas, params={"world.restitution": 0.9}, client=object())


def test_a_galton_board_sweep_counts_its_bins(client, preset):
    board = preset("09-galton-board.json")
    table = ps.sweep(board, params={"droppers[0].balls": [12], "droppers[0].seed": [1, 2]},
                     duration=4.0, observables=False, client=client)
    assert "temperature" not in table.columns
    for _, row in table.iterrows():
        assert len(row["bins"]) == 9
        assert row["bins_counted"] + row["bins_outside"] + row["bins_above"] == 12
        assert sum(row["bins"]) == row["bins_counted"]
    assert list(table["bins"][0]) != list(table["bins"][1])  # another seed, other paths
