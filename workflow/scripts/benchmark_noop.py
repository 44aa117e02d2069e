"""Nothing: rule benchmark_noop's job is timed for what any job pays before its work."""
