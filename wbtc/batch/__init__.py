"""`wbtc batch`: many runs of a plan on a process pool or a Ray cluster, graded into one table."""
