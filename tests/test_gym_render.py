"""Rendering through Gymnasium: "rgb_array" frames from the video renderer (so RecordVideo
writes a video), "human" in MuJoCo's viewer where a display exists, one line where none does."""

import imageio.v3 as iio
import numpy as np
import pytest
from gymnasium.wrappers import RecordVideo

import sailmujoco.gym  # noqa: F401  (registers the ids)
from sailmujoco.gym import SailGymEnv
from sailmujoco.viewer.window import NoDisplay


def test_record_video_writes_an_mp4(tmp_path):
    """Five steps of the robot's heading hold at 10 frames a second (one per 0.1 s control
    step): RecordVideo writes the reset frame and one per step, 64 x 48 pixels."""
    import gymnasium

    env = gymnasium.make("sailmujoco/SaoudRobot-HeadingHold-v0", render_mode="rgb_array",
                         render_width=64, render_height=48, time_limit=0.45)
    assert env.metadata["render_fps"] == pytest.approx(10.0)
    env = RecordVideo(env, str(tmp_path / "videos"), episode_trigger=lambda episode: True,
                      disable_logger=True)
    env.reset(seed=0)
    done = False
    while not done:
        _, _, terminated, truncated, _ = env.step(np.zeros(2, dtype=np.float32))
        done = terminated or truncated
    env.close()
    videos = sorted((tmp_path / "videos").glob("*.mp4"))
    assert len(videos) == 1
    frames = list(iio.imiter(videos[0]))
    assert len(frames) == 1 + 5
    assert frames[0].shape == (48, 64, 3)
    assert np.ptp(frames[-1]) > 50  # a picture, not a blank frame


def test_rgb_array_frames_show_the_boat_moving_in_a_paper_world():
    env = SailGymEnv("saoud_robot", "speed_trial", "paper", render_mode="rgb_array",
                     render_width=80, render_height=60, camera="top", time_limit=3.0)
    env.reset(seed=0)
    first = env.render()
    for _ in range(20):
        env.step(np.array([0.0, 0.5], dtype=np.float32))
    later = env.render()
    env.close()
    assert first.shape == later.shape == (60, 80, 3) and first.dtype == np.uint8
    assert not np.array_equal(first, later)


def test_human_rendering_without_a_display_says_so_in_one_line(monkeypatch):
    monkeypatch.delenv("DISPLAY", raising=False)
    monkeypatch.delenv("WAYLAND_DISPLAY", raising=False)
    with pytest.raises(NoDisplay) as err:
        SailGymEnv("saoud_robot", "heading_hold", render_mode="human")
    message = str(err.value)
    assert "\n" not in message and "render_mode='human' needs a display" in message
    assert "rgb_array" in message


def test_an_unknown_render_mode_is_refused():
    with pytest.raises(ValueError, match="render_mode must be None or one of"):
        SailGymEnv("saoud_robot", "heading_hold", render_mode="ansi")
