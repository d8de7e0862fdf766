"""Ten seconds of a real IMU: an x-io Technologies NGIMU moved by hand, with the device's own estimate.

Where the data come from
------------------------
The two files in ``coursekit/data/`` are copied (line endings aside) from the **scikit-kinematics 0.10.4** wheel
on PyPI (T. Haslwanter; ``tests/data/data_ngimu/sensors.csv`` and ``quaternion.csv``), under the
BSD licence reproduced in ``coursekit/data/NGIMU_LICENSE.txt``. They record an **x-io NGIMU**
(firmware v1.8) at 50 Hz for 10 s: its gyroscope, accelerometer, magnetometer and barometer, and
the quaternion of its onboard attitude filter (gyroscope and accelerometer only: the magnetometer was
switched off in the device's settings, so the device's heading is its own and drifts freely).

Units and frames, as :func:`load_ngimu` returns them
----------------------------------------------------
- ``t``: seconds from the first sample; samples are 20.0 ms apart on average (±0.7 ms).
- ``gyro``: body rates in rad/s (the file gives °/s).
- ``accel``: specific force in m/s² (the file gives g; ``GRAVITY`` m/s² per g), so a device at rest
  with its z axis up reads about (0, 0, +9.8).
- ``device_R_wb``: the device's estimate as the course's ``R_wb`` (body to world, world z up), one per
  sample of ``device_t``. The file's quaternion (w, x, y, z) is the *conjugate* of that: read with the
  course's ``quat_to_matrix`` it gives ``R_bw``. Measured: over 18 windows of 0.5 s, integrating the
  gyroscope agrees with the device's rotation read as ``R_bw`` to 1.5° on average, and with it read
  as ``R_wb`` only to 7.5° (``tests/test_recording.py`` holds both).

Examples
--------
>>> rec = load_ngimu()
>>> rec.gyro.shape, rec.accel.shape, rec.device_R_wb.shape
((499, 3), (499, 3), (499, 3, 3))
>>> round(float(np.median(np.diff(rec.t))), 3)   # s between samples: 50 Hz
0.02
"""

from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

import numpy as np
from scipy.spatial.transform import Rotation

from .imu import GRAVITY

__all__ = ["Recording", "load_ngimu", "DATA_FOLDER"]

DATA_FOLDER = Path(__file__).resolve().parent / "data"
SOURCE = (
    "x-io Technologies NGIMU, 10 s at 50 Hz, from the scikit-kinematics 0.10.4 wheel on PyPI "
    "(tests/data/data_ngimu; BSD licence, coursekit/data/NGIMU_LICENSE.txt)"
)


@dataclass(frozen=True)
class Recording:
    """A recorded IMU run and the device's own attitude estimate.

    Attributes
    ----------
    t : ndarray, shape (N,)
        Sample times, s, from 0.
    gyro : ndarray, shape (N, 3)
        Measured body rates, rad/s.
    accel : ndarray, shape (N, 3)
        Measured specific force in body axes, m/s².
    device_t : ndarray, shape (M,)
        Times of the device's estimates, s, on the same clock as ``t``.
    device_R_wb : ndarray, shape (M, 3, 3)
        The device's onboard estimate of the attitude, body to world.
    source : str
        Where the data come from.
    """

    t: np.ndarray
    gyro: np.ndarray
    accel: np.ndarray
    device_t: np.ndarray
    device_R_wb: np.ndarray
    source: str = SOURCE


def _matrices_bw(q):
    """Rotation matrices of unit quaternions (w, x, y, z) as rows, shape (M, 4) → (M, 3, 3)."""
    return Rotation.from_quat(q, scalar_first=True).as_matrix()   # normalises each row


@lru_cache(maxsize=1)
def _read():
    sensors = np.loadtxt(DATA_FOLDER / "ngimu_sensors.csv", delimiter=",", skiprows=1)
    estimates = np.loadtxt(DATA_FOLDER / "ngimu_quaternion.csv", delimiter=",", skiprows=1)
    start = sensors[0, 0]
    return sensors, estimates, start


def load_ngimu() -> Recording:
    """The NGIMU recording in the course's units and frames (a fresh copy on every call).

    Returns
    -------
    Recording
        499 samples over 10 s; see the module's docstring for units, frames and the source.
    """
    sensors, estimates, start = _read()
    R_bw = _matrices_bw(estimates[:, 1:5])
    return Recording(
        t=sensors[:, 0] - start,
        gyro=np.deg2rad(sensors[:, 1:4]),
        accel=sensors[:, 4:7] * GRAVITY,
        device_t=estimates[:, 0] - start,
        device_R_wb=np.transpose(R_bw, (0, 2, 1)).copy(),
    )
