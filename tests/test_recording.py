"""The real IMU recording (coursekit/recording.py): the file as copied, its units and its frames.

Oracles: the files' bytes (their SHA-256, line endings aside, as the scikit-kinematics 0.10.4 wheel
records them in its RECORD file, so a copy that was edited fails); gravity's size while the device
lies still (the first 40 ms); the gyroscope integrated over 0.5 s windows against the device's own
estimate read both ways, which is what says the file's quaternion is R_bw in the course's convention.
"""

import hashlib

import numpy as np
import pytest

from coursekit.imu import GRAVITY
from coursekit.lie import Exp, Log
from coursekit.recording import DATA_FOLDER, load_ngimu

PUBLISHED = {
    "ngimu_sensors.csv": "5bb127f5886477f71e405df9662e61291ecc6a2b9f01751a1983d87d8f32b38d",
    "ngimu_quaternion.csv": "097b0af6c59700b3ffb13c685d4dec4b2dc962520f39f94ffba4e9c5f577723b",
}


def _sha256(name):
    """The file's SHA-256 with the published line endings (CRLF; the copy keeps LF, as release writes text)."""
    return hashlib.sha256((DATA_FOLDER / name).read_bytes().replace(b"\n", b"\r\n")).hexdigest()


@pytest.mark.parametrize("name", sorted(PUBLISHED))
def test_the_files_are_the_published_ones(name):
    assert _sha256(name) == PUBLISHED[name]
    assert "scikit-kinematics 0.10.4" in (DATA_FOLDER / "NGIMU_LICENSE.txt").read_text(encoding="utf-8")


def test_shapes_rate_and_units():
    rec = load_ngimu()
    assert rec.t.shape == (499,) and rec.gyro.shape == rec.accel.shape == (499, 3)
    assert rec.device_R_wb.shape == (len(rec.device_t), 3, 3)
    assert rec.t[0] == 0.0 and np.all(np.diff(rec.t) > 0)
    assert np.median(np.diff(rec.t)) == pytest.approx(0.02, abs=5e-4)  # 50 Hz
    still = np.linalg.norm(rec.accel[:2], axis=1)  # the first two samples, before the hand moves it
    assert still == pytest.approx(GRAVITY, rel=0.01)
    assert np.max(np.linalg.norm(rec.gyro, axis=1)) > 2.0  # rad/s: turned briskly, in °/s it would be > 100
    R = rec.device_R_wb
    assert np.allclose(R @ np.transpose(R, (0, 2, 1)), np.eye(3), atol=1e-6)
    assert np.allclose(np.linalg.det(R), 1.0, atol=1e-6)


def _window_errors(rec, as_given):
    """Degrees between the gyroscope's rotation over each 0.5 s window and the device's, per window."""
    errors = []
    for k0 in range(0, 450, 25):
        k1 = k0 + 25
        R = np.eye(3)
        for k in range(k0, k1):
            R = R @ Exp(rec.gyro[k] * (rec.t[k + 1] - rec.t[k]))
        j0, j1 = (int(np.argmin(np.abs(rec.device_t - rec.t[k]))) for k in (k0, k1))
        A0, A1 = rec.device_R_wb[j0], rec.device_R_wb[j1]
        if not as_given:  # the other reading of the file's quaternion
            A0, A1 = A0.T, A1.T
        errors.append(np.degrees(np.linalg.norm(Log((A0.T @ A1).T @ R))))
    return np.array(errors)


def test_the_device_estimate_is_body_to_world():
    rec = load_ngimu()
    right, other = _window_errors(rec, True), _window_errors(rec, False)
    assert np.mean(right) < 3.0 and np.mean(other) > 5.0, (np.mean(right), np.mean(other))


def test_every_call_gives_a_fresh_copy():
    first = load_ngimu()
    first.gyro[:] = 0.0
    assert np.any(load_ngimu().gyro != 0.0)
