"""Reproducible studies and benchmarks of nonobtuse, each runnable by one command (see README.md).

A package so that the sweep runner can import task functions by name
(``experiments.termination_map:run_case``) in fresh case processes and on Dask workers, and so that tests
can import the experiments.
"""
