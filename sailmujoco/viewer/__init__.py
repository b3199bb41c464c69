"""MuJoCo's interactive viewer with a controller in the loop (:func:`sailmujoco.viewer.view.watch`)."""
