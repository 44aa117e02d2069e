"""Tests of a trained network (the paper's section 3): its trials in silico and on the robot's
body, and what each trial scores."""
