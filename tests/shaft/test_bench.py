"""Smoke test of bench/shaft.py: the batched solve and its plain-Python baseline agree case by case."""


def test_the_shaft_benchmark_paths_agree_case_by_case(load_bench):
    bench = load_bench("shaft")
    m = bench.measure(n=12, n_base=3, repeat=1)
    assert m["converged"] and m["base_converged"]
    assert m["diff"] < 1e-9
    assert m["elements"] >= 30 and m["bearings"] == 3
