"""Studies: one script per paper figure or table; each writes results/<study>/."""
