"""Controllers from the papers, one module per paper (plain objects: reset(seed), __call__)."""
