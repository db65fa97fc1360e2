"""Exit codes of the ``nonobtuse`` command, shared by every subcommand."""

EXIT_OK = 0  # success; for checks: every angle nonobtuse, every facet Gabriel
EXIT_VIOLATIONS = 1  # a check found violations
EXIT_INVALID = 2  # invalid input or options
EXIT_NOT_CONVERGED = 3  # a refinement stopped before converging (budget, time, minimum length, stalled)
