"""A real MEMS IMU, simulated: the sensor behind the EuRoC MAV dataset, the Analog Devices ADIS16448.

The lessons that use realistic data (08 and 09) draw their gyroscope and
accelerometer readings from :data:`IMU`, a model of one named sensor with published numbers. The
sensor is the **Analog Devices ADIS16448** ("iSensor ADIS16448, Compact, Precision Ten Degrees of
Freedom Inertial Sensor", data sheet, Analog Devices; Table 1, Specifications), the IMU of the
visual-inertial sensor that recorded the EuRoC MAV dataset (M. Burri et al., "The EuRoC micro aerial
vehicle datasets", International Journal of Robotics Research 35(10), 2016; the dataset's
``mav0/imu0/sensor.yaml``, "VI-Sensor IMU (ADIS16448)").

Where each number comes from, and its conversion
------------------------------------------------
``d = π/180`` rad per degree, ``g0 = 9.80665`` m/s² (standard gravity), 1 h = 3600 s.

==========================  ===================================  ==========================================
field                       source figure                        conversion
==========================  ===================================  ==========================================
``gyro_noise_density``      ADIS16448 Table 1, gyroscope         0.0135 °/s/√Hz × d
                            "rate noise density", 0.0135         = 2.356e-4 rad/s/√Hz
                            °/s/√Hz rms                          (cross-check: the angular random walk
                                                                 0.66 °/√h = 0.66/60 °/√s = 1.92e-4
                                                                 rad/s/√Hz, the same order)
``gyro_bias_random_walk``   EuRoC ``sensor.yaml``,               used as given: 1.9393e-5 rad/s²/√Hz
                            ``gyroscope_random_walk``            (the data sheet gives no rate random
                                                                 walk)
``gyro_bias_sigma0``        gyroscope in-run bias stability,     14.5 °/h × d / 3600 = 7.03e-5 rad/s
                            14.5 °/h: a typical value for this
                            class of part (see below)
``accel_noise_density``     ADIS16448 Table 1, accelerometer     0.23 mg/√Hz × 1e-3 × g0
                            "noise density", 0.23 mg/√Hz rms     = 2.256e-3 m/s²/√Hz
                                                                 (cross-check: the velocity random walk
                                                                 0.11 m/s/√h = 0.11/60 m/s/√s = 1.83e-3
                                                                 m/s²/√Hz, the same order)
``accel_bias_random_walk``  EuRoC ``sensor.yaml``,               used as given: 3.0e-3 m/s³/√Hz
                            ``accelerometer_random_walk``
``accel_bias_sigma0``       accelerometer in-run bias            0.25 mg × 1e-3 × g0 = 2.45e-3 m/s²
                            stability, 0.25 mg: a typical value
                            for this class of part (see below)
``rate_hz``                 EuRoC ``sensor.yaml``, ``rate_hz``   200 Hz (the rate EuRoC recorded at)
==========================  ===================================  ==========================================

How sure each figure is: the EuRoC ``sensor.yaml`` values (200 Hz, 1.6968e-4 rad/s/√Hz,
1.9393e-5 rad/s²/√Hz, 2.0e-3 m/s²/√Hz, 3.0e-3 m/s³/√Hz) agree across many public copies of that
file. The four data-sheet noise figures (0.0135 °/s/√Hz, 0.66 °/√h, 0.23 mg/√Hz, 0.11 m/s/√h) come
from public code that quotes the data sheet, not from the PDF itself, so no revision of it is named
here. The two in-run bias stabilities (14.5 °/h and 0.25 mg) are typical values for this class of
MEMS part and were not checked against the current revision of the data sheet: they set a realistic
size for the bias, not this part's specification. (EuRoC's own white-noise densities,
1.6968e-4 rad/s/√Hz and 2.0e-3 m/s²/√Hz, are within 30 % of the data sheet's.)

What is modelled, and what is not
---------------------------------
Each axis of each sensor reads the truth plus a bias plus white noise:

- **white noise**, independent per sample and axis, with the per-sample standard deviation
  σ = density × √rate (a density in units/√Hz sampled at ``rate_hz``);
- a **bias** that starts at N(0, σ0²) per axis (the in-run bias stability used as the spread) and then
  **random-walks**: b[k+1] = b[k] + σ_bw √dt · N(0, 1) per axis.

Not modelled: scale-factor error and non-linearity, axis misalignment and cross-axis sensitivity,
temperature dependence of bias and scale, g-sensitivity of the gyroscope, quantisation and the
sensor's internal filtering, the flicker (1/f) part of the bias instability, vibration and
rectification. The magnetometer and barometer of the ADIS16448 are not modelled either.

Frames: the world's z axis points up; ``R_wb`` maps body coordinates to world coordinates, so a
vector v_b in the body frame is ``R_wb @ v_b`` in the world frame.

Examples
--------
>>> from coursekit.imu import IMU, simulate_gyro, smooth_motion
>>> round(IMU.dt, 6), f"{IMU.gyro_noise_sigma:.2e} rad/s", f"{IMU.accel_noise_sigma:.3f} m/s²"
(0.005, '3.33e-03 rad/s', '0.032 m/s²')
>>> R_wb, omega_b = smooth_motion(1.0)
>>> R_wb.shape, omega_b.shape
((201, 3, 3), (200, 3))
>>> measured, bias = simulate_gyro(omega_b)
>>> measured.shape, bias.shape
((200, 3), (200, 3))
"""

from dataclasses import dataclass

import numpy as np

__all__ = ["ImuModel", "IMU", "GRAVITY", "smooth_motion", "simulate_gyro", "simulate_accelerometer"]

GRAVITY = 9.80665  # m/s², standard gravity; the world's z axis points up

_DEG = np.pi / 180.0
_HOUR = 3600.0


@dataclass(frozen=True)
class ImuModel:
    """Noise model of a six-axis IMU: white noise plus a random-walking bias on every axis.

    Densities are continuous-time (per √Hz); the per-sample standard deviations at ``rate_hz``
    are the properties :attr:`gyro_noise_sigma` and :attr:`accel_noise_sigma`.
    """

    name: str  # e.g. "Analog Devices ADIS16448"
    citation: str  # data sheet title, revision, table the numbers come from
    rate_hz: float  # sampling rate, Hz
    gyro_noise_density: float  # rad/s/√Hz (white noise; angular random walk)
    gyro_bias_random_walk: float  # rad/s²/√Hz (rate of the bias's random walk)
    gyro_bias_sigma0: float  # rad/s, spread of the bias at switch-on (in-run instability)
    accel_noise_density: float  # m/s²/√Hz
    accel_bias_random_walk: float  # m/s³/√Hz
    accel_bias_sigma0: float  # m/s²

    @property
    def dt(self) -> float:
        """Sampling interval, s (1 / ``rate_hz``)."""
        return 1.0 / self.rate_hz

    @property
    def gyro_noise_sigma(self) -> float:
        """Per-sample standard deviation of the gyroscope's white noise, rad/s (density × √rate)."""
        return self.gyro_noise_density * np.sqrt(self.rate_hz)

    @property
    def accel_noise_sigma(self) -> float:
        """Per-sample standard deviation of the accelerometer's white noise, m/s² (density × √rate)."""
        return self.accel_noise_density * np.sqrt(self.rate_hz)


IMU = ImuModel(
    name="Analog Devices ADIS16448",
    citation=(
        "Analog Devices, 'iSensor ADIS16448: Compact, Precision Ten Degrees of Freedom Inertial Sensor', "
        "data sheet, Table 1 (Specifications): gyroscope rate noise density 0.0135 °/s/√Hz and accelerometer "
        "noise density 0.23 mg/√Hz; in-run bias stabilities of 14.5 °/h and 0.25 mg, typical for this class of "
        "part (not checked against the current revision); bias random walks and the 200 Hz rate from the EuRoC "
        "MAV dataset's mav0/imu0/sensor.yaml (Burri et al., IJRR 35(10), 2016)"
    ),
    rate_hz=200.0,
    gyro_noise_density=0.0135 * _DEG,  # 0.0135 °/s/√Hz → 2.356e-4 rad/s/√Hz
    gyro_bias_random_walk=1.9393e-5,  # rad/s²/√Hz, EuRoC sensor.yaml
    gyro_bias_sigma0=14.5 * _DEG / _HOUR,  # 14.5 °/h → 7.03e-5 rad/s
    accel_noise_density=0.23e-3 * GRAVITY,  # 0.23 mg/√Hz → 2.256e-3 m/s²/√Hz
    accel_bias_random_walk=3.0e-3,  # m/s³/√Hz, EuRoC sensor.yaml
    accel_bias_sigma0=0.25e-3 * GRAVITY,  # 0.25 mg → 2.45e-3 m/s²
)

# Separate random streams for the motion, the gyroscope and the accelerometer, so that the same
# seed never gives the two sensors the same noise.
_STREAM_MOTION, _STREAM_GYRO, _STREAM_ACCEL = 0, 1, 2


def _rng(seed, stream):
    return np.random.default_rng([int(seed), stream])


def _exp_many(phi):
    """Rodrigues' formula for every row of ``phi`` (shape (N, 3)); returns (N, 3, 3)."""
    theta = np.linalg.norm(phi, axis=1)
    K = np.zeros((len(phi), 3, 3))
    K[:, 0, 1], K[:, 0, 2], K[:, 1, 2] = -phi[:, 2], phi[:, 1], -phi[:, 0]
    K[:, 1, 0], K[:, 2, 0], K[:, 2, 1] = phi[:, 2], -phi[:, 1], phi[:, 0]
    small = theta < 1e-4
    t = np.where(small, 1.0, theta)
    a = np.where(small, 1.0 - theta**2 / 6.0 + theta**4 / 120.0, np.sin(t) / t)
    b = np.where(small, 0.5 - theta**2 / 24.0 + theta**4 / 720.0, (1.0 - np.cos(t)) / t**2)
    return np.eye(3) + a[:, None, None] * K + b[:, None, None] * (K @ K)


def _random_rotation(rng):
    from scipy.spatial.transform import Rotation  # imported here: most users of this module never call it

    return Rotation.from_quat(rng.standard_normal(4), scalar_first=True).as_matrix()  # a uniform random rotation


def smooth_motion(duration_s, rate_hz=None, seed=0):
    """A smooth, seeded attitude trajectory and its true body angular velocity.

    The body rate on each axis is a sum of three sinusoids (0.05 to 0.5 Hz, amplitudes up to
    about 1 rad/s in total), the start attitude is a seeded random rotation, and the attitude
    is propagated exactly, with the body rate held over each sampling interval ``dt = 1 / rate_hz``.

    Parameters
    ----------
    duration_s : float, length of the trajectory, s; N = round(duration_s * rate_hz) intervals.
    rate_hz : float, sampling rate, Hz; defaults to ``IMU.rate_hz``.
    seed : int, the same seed gives the same trajectory.

    Returns
    -------
    R_wb : array (N + 1, 3, 3), body-to-world rotations at t = 0, dt, ..., N dt.
    omega_b : array (N, 3), true body angular velocity over each interval, rad/s.

    Examples
    --------
    >>> R_wb, omega_b = smooth_motion(2.0, rate_hz=100.0)
    >>> R_wb.shape, omega_b.shape
    ((201, 3, 3), (200, 3))
    >>> bool(np.allclose(R_wb[5].T @ R_wb[5], np.eye(3)))
    True
    """
    rate_hz = IMU.rate_hz if rate_hz is None else float(rate_hz)
    dt = 1.0 / rate_hz
    n = int(round(float(duration_s) * rate_hz))
    rng = _rng(seed, _STREAM_MOTION)
    freq = rng.uniform(0.05, 0.5, size=(3, 3))  # (axis, component), Hz
    amp = rng.uniform(0.1, 0.35, size=(3, 3))  # rad/s
    phase = rng.uniform(0.0, 2.0 * np.pi, size=(3, 3))
    t = (np.arange(n) + 0.5) * dt
    omega_b = np.sum(amp * np.sin(2.0 * np.pi * freq * t[:, None, None] + phase), axis=2)
    R_wb = np.empty((n + 1, 3, 3))
    R_wb[0] = _random_rotation(rng)
    for k in range(n):
        # a spin about the world axis R ω_b, as lesson 03 writes one (dR/dt = [ω_w]× R with ω_w = R ω_b)
        R_wb[k + 1] = _exp_many((R_wb[k] @ omega_b[k] * dt)[None])[0] @ R_wb[k]
    return R_wb, omega_b


def _bias_walk(n, sigma0, random_walk, dt, rng):
    b0 = sigma0 * rng.standard_normal(3)
    steps = random_walk * np.sqrt(dt) * rng.standard_normal((n, 3))
    steps[0] = 0.0
    return b0 + np.cumsum(steps, axis=0)


def simulate_gyro(omega_b, model=IMU, seed=0):
    """Gyroscope readings of the true body rates ``omega_b``: truth + bias + white noise.

    The bias starts at N(0, ``model.gyro_bias_sigma0``²) per axis and random-walks with steps of
    standard deviation ``model.gyro_bias_random_walk * sqrt(model.dt)``; the white noise has
    per-sample standard deviation ``model.gyro_noise_sigma``.

    Parameters
    ----------
    omega_b : array (N, 3), true body angular velocity, rad/s (left unchanged).
    model : ImuModel, the sensor; defaults to :data:`IMU`.
    seed : int, the same seed gives the same readings.

    Returns
    -------
    measured : array (N, 3), rad/s.
    bias : array (N, 3), the bias in each sample, rad/s (so ``measured - omega_b - bias`` is the
        white noise).

    Examples
    --------
    >>> measured, bias = simulate_gyro(np.zeros((1000, 3)))
    >>> bool(abs(np.std(measured - bias) / IMU.gyro_noise_sigma - 1) < 0.1)
    True
    """
    omega_b = np.array(omega_b, dtype=float).reshape(-1, 3)
    n = len(omega_b)
    rng = _rng(seed, _STREAM_GYRO)
    bias = _bias_walk(n, model.gyro_bias_sigma0, model.gyro_bias_random_walk, model.dt, rng)
    noise = model.gyro_noise_sigma * rng.standard_normal((n, 3))
    return omega_b + bias + noise, bias


def simulate_accelerometer(R_wb, model=IMU, seed=0, accel_w=None):
    """Accelerometer readings (specific force in the body frame) along the attitudes ``R_wb``.

    Each sample reads ``R_wb[k].T @ (accel_w[k] + GRAVITY * z)`` plus a random-walking bias plus
    white noise: at rest it measures gravity's reaction, pointing up, in body coordinates. The bias
    starts at N(0, ``model.accel_bias_sigma0``²) per axis and random-walks with steps of standard
    deviation ``model.accel_bias_random_walk * sqrt(model.dt)``; the white noise has per-sample
    standard deviation ``model.accel_noise_sigma``.

    Parameters
    ----------
    R_wb : array (N, 3, 3), body-to-world rotations, one per sample (left unchanged).
    model : ImuModel, the sensor; defaults to :data:`IMU`.
    seed : int, the same seed gives the same readings.
    accel_w : array (N, 3), the body's acceleration in the world frame, m/s²; default zero (the
        body only turns).

    Returns
    -------
    measured : array (N, 3), m/s².
    bias : array (N, 3), the bias in each sample, m/s².

    Examples
    --------
    >>> measured, bias = simulate_accelerometer(np.repeat(np.eye(3)[None], 400, axis=0))
    >>> bool(np.allclose(measured.mean(axis=0), [0.0, 0.0, GRAVITY], atol=0.05))
    True
    """
    R_wb = np.array(R_wb, dtype=float).reshape(-1, 3, 3)
    n = len(R_wb)
    f_w = np.zeros((n, 3)) if accel_w is None else np.array(accel_w, dtype=float).reshape(n, 3)
    f_w = f_w + np.array([0.0, 0.0, GRAVITY])
    truth = np.einsum("kji,kj->ki", R_wb, f_w)  # R_wb[k].T @ f_w[k]
    rng = _rng(seed, _STREAM_ACCEL)
    bias = _bias_walk(n, model.accel_bias_sigma0, model.accel_bias_random_walk, model.dt, rng)
    noise = model.accel_noise_sigma * rng.standard_normal((n, 3))
    return truth + bias + noise, bias
