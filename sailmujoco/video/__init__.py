"""Offscreen video of a task run: a boat sailing under a controller, written as an H.264 mp4.

Example::

    from sailmujoco import video
    video.record("wille_yacht", "beam_reach_roll", "wille_roll", "beam_reach.mp4", seconds=30)

or ``sailmujoco video wille_yacht beam_reach_roll --controller wille_roll --seconds 30
--out beam_reach.mp4`` (``python -m sailmujoco.video ...`` takes the same arguments; the command
is :mod:`sailmujoco.cli.video`).

What a frame shows
    On the left, the 3-D scene: the boat as MuJoCo draws it (hull, keel, mast, boom and sail on
    the ``sail`` joint, rudder blade on the ``rudder`` joint), heeling and pitching with the hull,
    on a see-through sea with a wave texture that moves under the camera, deep blue water under
    it and a sky gradient above (:mod:`~sailmujoco.video.water`); in a sea (``waves``, or the
    simulation's own; ``--waves KEY=VALUE`` on the command line, :mod:`sailmujoco.cli.waves`)
    the surface around the boat moves with the waves' elevation, lit by a low sun over the
    waves' bearing (:mod:`~sailmujoco.video.sea`). Added to MuJoCo's scene: the
    true-wind arrow centred just above the masthead (cyan, pointing where the wind blows to,
    0.12 masthead heights per m/s); with ``forces``, the sail, keel and rudder force vectors at
    ``sail_ce``, ``keel_cp`` and ``rudder_cp`` (red, green, orange; 1.3 masthead heights for
    0.5 rho_air A_sail U^2, U the true wind speed of the first frame, clipped at 2.2 masthead
    heights); for position keeping, the target buoy and
    the target and pre-arrival circles. With ``overlay``, a panel of its own on the right
    (:mod:`~sailmujoco.video.panel`; the scene is rendered beside it, so nothing is drawn over
    the boat or its arrows): a map seen from above, north up, with the track so far, the
    heading, the desired heading or course or the target, the true wind, a north arrow and a
    scale bar; under it the time, heading and its reference, speed, heel, true and apparent
    wind, rudder and sail angles, and the colour key.

Cameras (``camera``)
    ``"follow"``: rides with the boat from ``follow_distance`` m (default 2.7 masthead heights),
    looking down ``follow_elevation_deg`` (default -24). Its bearing from the bow puts it on
    the side away from the boom, part of the way from dead astern to the sail's normal, so
    that the sail shows its face on every point of sail; it swings round through a
    first-order lag of ``follow_lag`` s when the boom crosses over, and its azimuth follows the
    heading through the same lag (:mod:`~sailmujoco.video.camera`). ``follow_bearing_deg``
    (counter-clockwise from the bow) fixes the bearing instead.
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
    ends with its last frame, marked with the reason, held for one second. So does a run whose
    controller raises or gives a bad action (not two finite numbers): the video ends at the
    state the controller was given and is kept; :func:`record` then raises
    :class:`~sailmujoco.errors.ControllerFailed` (its ``kept``: the :class:`Recording`), and
    ``sailmujoco video`` says so in one line, with the simulated time, and exits with status 2.

What is drawn is a display copy of the boat (:func:`display_model`), compiled from the same
parameters and given the simulated pose each frame; the simulation's own model is never touched.

Rendering needs an OpenGL platform: the one ``MUJOCO_GL`` names, or EGL when it is unset,
loaded at the first frame (:mod:`sailmujoco.gl_platform`). :func:`record`, the Gymnasium
environments' ``render_mode="rgb_array"`` and the film of ``sailmujoco sitl`` load it in a child
process that draws the frames (:class:`ChildRenderer`, :mod:`~sailmujoco.video.child`), never in
the caller's: Mesa's EGL brings its own LLVM, and PyTorch's triton loaded after it in the same
process crashes it. A :class:`SceneRenderer` made directly draws in the caller's process.
Mesa's EGL renders on the CPU (Debian packages ``libegl1 libegl-mesa0 libgl1-mesa-dri``), the
NVIDIA driver's on a GPU.
The fallback is OSMesa: ``apt-get install libosmesa6`` and ``MUJOCO_GL=osmesa``. Without a platform,
:class:`RenderingUnavailable` says so and names these fixes. Shadows and reflections are off.
The mp4 is encoded by the ffmpeg binary that the ``imageio-ffmpeg`` package ships.

Modules
    ``scene``: :class:`Snapshot`, :func:`display_model`, :class:`SceneRenderer`;
    ``camera``: the follow camera and the top view; ``water``: the sea of the display model;
    ``overlays``: the arrows and target circles; ``panel``: the map and the numbers beside the
    scene; ``recording``: :func:`record`,
    :class:`Recording`, :func:`record_study_scenario`; ``child``: :class:`ChildRenderer`, a
    ``SceneRenderer`` in a child process; ``gl``: the OpenGL platform and
    :class:`RenderingUnavailable`.
"""

from .camera import FollowCamera, boom_angle, yaw_of
from .child import ChildRenderer
from .gl import FIX, RenderingUnavailable, check_rendering
from .overlays import COLOURS, FORCES, MAX_ARROW, WIND_ARROW_PER_MPS
from .panel import KNOT, MapView
from .recording import (
    Recording,
    frames_between_substeps,
    record,
    record_study_scenario,
    scene_of,
    simulated_sea,
)
from .scene import (
    CAMERAS,
    FORCE_ARROW,
    FORCE_SITES,
    REFERENCE_WIND,
    SceneRenderer,
    Snapshot,
    close_outward,
    display_model,
    snapshot_observation,
    snapshot_physics,
)
from .water import SEA_ALPHA

__all__ = ["CAMERAS", "COLOURS", "FIX", "FORCES", "FORCE_ARROW", "FORCE_SITES", "KNOT", "MAX_ARROW",
           "REFERENCE_WIND", "SEA_ALPHA", "WIND_ARROW_PER_MPS", "ChildRenderer", "FollowCamera", "MapView",
           "Recording",
           "RenderingUnavailable", "SceneRenderer", "Snapshot", "boom_angle", "check_rendering",
           "close_outward", "display_model", "frames_between_substeps", "record",
           "record_study_scenario", "scene_of", "simulated_sea", "snapshot_observation",
           "snapshot_physics", "yaw_of"]
