"""Studies: one per paper figure or table, each a declared study writing results/<study>/."""
