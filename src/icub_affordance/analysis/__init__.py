"""The analysis of the trials (the paper's results, and the tests added to them): the statistics,
the paper's claims and their confirmation on fresh networks, the declared readings and studies,
the robot's effects, and the verdicts' thresholds."""
