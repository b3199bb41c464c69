"""dm_control-style tasks over the MuJoCo boats and the papers' reduced models."""
