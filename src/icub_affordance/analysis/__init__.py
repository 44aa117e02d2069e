"""The analysis of the trials (the paper's results, and the tests added to them): the statistics,
tests over replications, the paper's claims and their confirmation on fresh networks, the
declared readings and studies, the hidden states, the robot's effects and contact times, and the
verdicts' thresholds."""
