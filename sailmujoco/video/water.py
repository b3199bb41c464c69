"""The sea of the display model: a wave texture on the surface and dark deep water under it.

The surface (the scene's ``sea_surface`` plane, material ``sea``) is drawn see-through
(opacity :data:`SEA_ALPHA`) so that the keel, the rudder blade and their force arrows show
under it. Under the surface, out of reach of every foil, lies an opaque plane of deep-water
blue (:data:`DEEP`), so that what shows through the surface is water, not the sky box. The
surface's texture (:func:`wave_texture`) is a tileable sum of sine waves, shaded from deep to
light blue with pale crests: it moves under a following camera, which shows the boat's speed,
without the checker board of a floor. One texture tile spans :data:`TILE_HULLS` hull lengths.

Only the display copy of the boat carries these changes; the simulated model is never touched.
"""

from __future__ import annotations

import numpy as np

SEA_ALPHA = 0.5  # opacity of the display sea's surface
DEEP = (0.04, 0.2, 0.36, 1.0)  # colour of the opaque deep-water plane
TILE_HULLS = 2.0  # hull lengths of water per texture tile
TROUGH = np.array([22.0, 78.0, 128.0])  # texture colours (0-255): wave troughs ...
CREST = np.array([62.0, 128.0, 178.0])  # ... wave crests ...
FOAM = np.array([175.0, 205.0, 228.0])  # ... and the highest crests


def wave_texture(size: int, seed: int = 7) -> np.ndarray:
    """A tileable sea texture: (size, size, 3) uint8 RGB.

    The height field h(u, v) = sum_k a_k sin(2 pi (m_k u + n_k v) + phi_k) has integer wave
    numbers (m_k, n_k), so it tiles seamlessly; amplitudes fall as 1/|k| (longer waves higher).
    Colours run from :data:`TROUGH` to :data:`CREST` with height, and towards :data:`FOAM` on
    the highest one per cent.

    Parameters
    ----------
    size : int
        Pixels along each side.
    seed : int
        Seeds the wave numbers and phases (the same seed, the same texture).
    """
    rng = np.random.default_rng(seed)
    u = np.arange(size) / size
    uu, vv = np.meshgrid(u, u, indexing="xy")
    height = np.zeros((size, size))
    for _ in range(24):
        k = rng.uniform(3.0, 16.0)
        angle = rng.uniform(0.0, np.pi)
        m, n = round(k * np.cos(angle)), round(k * np.sin(angle))
        if m == 0 and n == 0:
            continue
        height += np.sin(2.0 * np.pi * (m * uu + n * vv) + rng.uniform(0.0, 2.0 * np.pi)) / np.hypot(m, n)
    height = (height - height.mean()) / height.std()
    level = np.clip(0.5 + 0.25 * height, 0.0, 1.0)[..., None]
    colour = TROUGH + (CREST - TROUGH) * level
    foam = np.clip((height - np.quantile(height, 0.99)) / 0.8, 0.0, 0.7)[..., None]
    colour = colour + (FOAM - colour) * foam
    return np.clip(colour, 0, 255).astype(np.uint8)


def add_deep_water(spec, depth: float) -> None:
    """Add the opaque deep-water plane ``depth`` m under the surface to a scene's ``MjSpec``.

    Parameters
    ----------
    spec : mujoco.MjSpec
        The display scene (never the simulated one).
    depth : float
        Depth of the plane, m: below the deepest foil.
    """
    import mujoco

    spec.worldbody.add_geom(name="deep_water", type=mujoco.mjtGeom.mjGEOM_PLANE,
                            size=[2000.0, 2000.0, 1.0], pos=[0.0, 0.0, -depth], rgba=list(DEEP),
                            contype=0, conaffinity=0, group=1)


def paint_sea(model, hull_length: float, contrast: float = 1.0, gain: float = 1.0) -> None:
    """Give the compiled display model's ``sea`` material the wave texture and its opacity.

    Parameters
    ----------
    model : mujoco.MjModel
        The display model (its ``sea`` texture is RGB, square).
    hull_length : float
        m: one texture tile spans :data:`TILE_HULLS` of them.
    contrast : float
        The texture's colours drawn towards their mean: 1 as :func:`wave_texture` makes them,
        0 one flat colour.
    gain : float
        The texture's colours multiplied by this (clipped at white).
    """
    texture = model.texture("sea")
    size, channels = int(model.tex_width[texture.id]), int(model.tex_nchannel[texture.id])
    start = int(model.tex_adr[texture.id])
    pixels = wave_texture(size)
    if contrast != 1.0 or gain != 1.0:
        mean = pixels.reshape(-1, 3).mean(axis=0)
        pixels = np.clip(gain * (mean + contrast * (pixels - mean)), 0, 255).astype(np.uint8)
    if channels == 4:
        pixels = np.concatenate([pixels, np.full((size, size, 1), 255, np.uint8)], axis=2)
    model.tex_data[start:start + pixels.size] = pixels.ravel()
    sea = model.material("sea")
    model.mat_texrepeat[sea.id] = 1.0 / (TILE_HULLS * hull_length)  # texuniform: repeats per metre
    model.mat_rgba[sea.id] = (1.0, 1.0, 1.0, SEA_ALPHA)
    model.mat_reflectance[sea.id] = 0.0
