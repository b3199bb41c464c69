"""Offscreen video of a task run: a boat sailing under a controller, written as an H.264 mp4.

Example::

    from sailmujoco import video
    video.record("wille_yacht", "beam_reach_roll", "wille_roll", "beam_reach.mp4", seconds=30)

or ``sailmujoco video wille_yacht beam_reach_roll --controller wille_roll --seconds 30
--out beam_reach.mp4`` (``python -m sailmujoco.video ...`` takes the same arguments).

What a frame shows
    The boat as MuJoCo draws it (hull, keel, mast, boom and sail on the ``sail`` joint, rudder
    blade on the ``rudder`` joint), heeling and pitching with the hull, on the sea plane whose
    checker grid (squares of 1/8 hull length) shows the speed. Added to MuJoCo's scene: the
    true-wind arrow centred just above the masthead (cyan, pointing where the wind blows to,
    6 % of the masthead height per m/s); with ``forces``, the sail, keel and rudder force
    vectors at ``sail_ce``, ``keel_cp`` and ``rudder_cp`` (red, green, orange; 1.5 masthead
    heights for 0.5 rho_air A_sail (10 m/s)^2, clipped at 2); for position keeping, the target
    buoy and the target and pre-arrival circles. With ``overlay``, a text box (time, speed over
    ground, heel, apparent wind angle and speed at the masthead, rudder and sail angles,
    distance to the target) and a colour legend are drawn with PIL. The sea is drawn
    see-through so that the keel, the rudder blade and their forces show.

Cameras (``camera``)
    ``"follow"``: chases the boat from ``follow_distance`` m (default 2.3 masthead heights) at
    ``follow_bearing_deg`` from the bow (counter-clockwise, default 150: the port quarter) and
    ``follow_elevation_deg`` above the horizon; its azimuth follows the heading through a
    first-order lag of ``follow_lag`` s, so a turn shows as the hull turning on the grid.
    ``"top"``: looks straight down, north up. For tasks with a target (position keeping) it is
    fixed over the target area, start and circles; otherwise it rides above the boat. Give
    ``top_center=(x, y)`` (m) and ``top_extent`` (m, half-height of the view on the water) for
    any fixed view. ``"side"``: the boat model's own ``side`` camera (tracks the hull's centre
    of mass, fixed orientation).

Timing
    Frame k shows the state at t = k / fps whatever the control rate. In the MuJoCo world each
    control step's physics sub-steps are split at the frame times, which leaves the trajectory
    unchanged bit for bit (:meth:`sailmujoco.physics.BoatPhysics.step`). A paper world moves by
    whole control steps (its integrator is adaptive), so frame k shows the state at the end of
    the control step that contains t = k / fps (the text box gives that state's time). A
    ``seconds`` run gives ``round(seconds * fps)`` frames; a run that stops early (capsize)
    ends with its last frame, marked with the reason, held for one second.

What is drawn is a display copy of the boat (:func:`display_model`), compiled from the same
parameters and given the simulated pose each frame; the simulation's own model is never touched.

Rendering needs an OpenGL platform, named by ``MUJOCO_GL`` before Python starts. sailmujoco
sets ``MUJOCO_GL=egl`` unless it is set: Mesa's llvmpipe renders on the CPU (Debian packages
``libegl1 libegl-mesa0 libgl1-mesa-dri``), the NVIDIA driver on a GPU. The fallback is OSMesa:
``apt-get install libosmesa6`` and ``MUJOCO_GL=osmesa``. Without a platform,
:class:`RenderingUnavailable` says so and names these fixes. Shadows and reflections are off.
The mp4 is encoded by the ffmpeg binary that the ``imageio-ffmpeg`` package ships.

Modules
    ``scene``: :class:`Snapshot`, :func:`display_model`, :class:`SceneRenderer`;
    ``overlays``: the arrows, target circles and text box; ``recording``: :func:`record`,
    :class:`Recording`, :func:`record_study_scenario`; ``gl``: the OpenGL platform and
    :class:`RenderingUnavailable`; ``command``: the ``sailmujoco video`` command.
"""

from ..arguments import check_settings
from .command import add_parser, main, run_cli
from .gl import FIX, RenderingUnavailable, check_rendering
from .overlays import COLOURS, FORCES, KNOT, MAX_ARROW, WIND_ARROW_PER_MPS
from .recording import Recording, frames_between_substeps, record, record_study_scenario, scene_of
from .scene import (
    CAMERAS,
    FORCE_ARROW,
    FORCE_SITES,
    REFERENCE_WIND,
    SEA_ALPHA,
    SceneRenderer,
    Snapshot,
    close_outward,
    display_model,
    snapshot_observation,
    snapshot_physics,
    yaw_of,
)

__all__ = ["CAMERAS", "COLOURS", "FIX", "FORCES", "FORCE_ARROW", "FORCE_SITES", "KNOT", "MAX_ARROW",
           "REFERENCE_WIND", "SEA_ALPHA", "WIND_ARROW_PER_MPS", "Recording", "RenderingUnavailable",
           "SceneRenderer", "Snapshot", "add_parser", "check_rendering", "check_settings",
           "close_outward", "display_model", "frames_between_substeps", "main", "record",
           "record_study_scenario", "run_cli", "scene_of", "snapshot_observation", "snapshot_physics",
           "yaw_of"]
