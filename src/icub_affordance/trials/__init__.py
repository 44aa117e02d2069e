"""Tests of a trained network (the paper's section 3): its trials in silico and on the robot's
body, what each trial scores, its hidden states, and when the fingers make contact."""
