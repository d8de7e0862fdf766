"""The IMU model in coursekit.imu: its noise has the stated statistics, its motion is exact, its seeds reproduce."""

import subprocess
import sys

import numpy as np
import pytest
from scipy.stats import chi2

from coursekit.imu import GRAVITY, IMU, ImuModel, simulate_accelerometer, simulate_gyro, smooth_motion
from coursekit.lie import Exp

P_TAIL = 1e-4  # each χ² test rejects a correct model with probability 2e-4


def assert_sigma(samples, sigma):
    """``samples`` (any shape) are i.i.d. N(0, sigma²): their sum of squares lies within χ² bounds."""
    z = np.asarray(samples).ravel() / sigma
    n = z.size
    lo, hi = chi2.ppf(P_TAIL, n), chi2.ppf(1 - P_TAIL, n)
    s = float(z @ z)
    assert lo < s < hi, f"sum of squares {s:.1f} of {n} samples outside χ² bounds [{lo:.1f}, {hi:.1f}]"
    assert abs(z.mean()) < 5 / np.sqrt(n)


def test_units_follow_the_datasheet_figures():
    deg, g0 = np.pi / 180, 9.80665
    assert IMU.gyro_noise_density == pytest.approx(0.0135 * deg)
    assert IMU.gyro_bias_sigma0 == pytest.approx(14.5 * deg / 3600)
    assert IMU.accel_noise_density == pytest.approx(0.23e-3 * g0)
    assert IMU.accel_bias_sigma0 == pytest.approx(0.25e-3 * g0)
    assert IMU.rate_hz == 200.0 and IMU.dt == pytest.approx(0.005)
    assert IMU.gyro_noise_sigma == pytest.approx(IMU.gyro_noise_density / np.sqrt(IMU.dt))
    assert IMU.accel_noise_sigma == pytest.approx(IMU.accel_noise_density / np.sqrt(IMU.dt))
    assert "ADIS16448" in IMU.name and "Table 1" in IMU.citation
    with pytest.raises(AttributeError):
        IMU.rate_hz = 100.0  # frozen


def test_gyro_white_noise_and_bias_walk_have_the_stated_sigma():
    _, omega_b = smooth_motion(20.0, seed=3)
    measured, bias = simulate_gyro(omega_b, seed=5)
    assert measured.shape == bias.shape == omega_b.shape == (4000, 3)
    assert_sigma(measured - omega_b - bias, IMU.gyro_noise_sigma)
    assert_sigma(np.diff(bias, axis=0), IMU.gyro_bias_random_walk * np.sqrt(IMU.dt))


def test_accelerometer_white_noise_and_bias_walk_have_the_stated_sigma():
    R_wb, _ = smooth_motion(20.0, seed=3)
    measured, bias = simulate_accelerometer(R_wb, seed=5)
    truth = np.einsum("kji,j->ki", R_wb, [0.0, 0.0, GRAVITY])
    assert measured.shape == bias.shape == (4001, 3)
    assert_sigma(measured - truth - bias, IMU.accel_noise_sigma)
    assert_sigma(np.diff(bias, axis=0), IMU.accel_bias_random_walk * np.sqrt(IMU.dt))


def test_initial_biases_have_the_stated_spread():
    b_gyro = np.array([simulate_gyro(np.zeros((1, 3)), seed=s)[1][0] for s in range(300)])
    b_accel = np.array([simulate_accelerometer(np.eye(3)[None], seed=s)[1][0] for s in range(300)])
    assert_sigma(b_gyro, IMU.gyro_bias_sigma0)
    assert_sigma(b_accel, IMU.accel_bias_sigma0)


def test_another_model_scales_the_noise():
    quiet = ImuModel("quiet", "none", 100.0, 1e-6, 0.0, 0.0, 1e-5, 0.0, 0.0)
    measured, bias = simulate_gyro(np.ones((2000, 3)), model=quiet, seed=1)
    assert np.all(bias == 0.0)
    assert_sigma(measured - 1.0, 1e-6 * 10.0)


@pytest.mark.parametrize("rate_hz", [None, 50.0, 1000.0])
def test_smooth_motion_is_exactly_integrated(rate_hz):
    R_wb, omega_b = smooth_motion(3.0, rate_hz=rate_hz, seed=7)
    dt = 1.0 / (rate_hz or IMU.rate_hz)
    n = int(round(3.0 / dt))
    assert R_wb.shape == (n + 1, 3, 3) and omega_b.shape == (n, 3)
    for k in range(0, n, max(1, n // 40)):
        np.testing.assert_allclose(R_wb[k + 1], R_wb[k] @ Exp(omega_b[k] * dt), atol=1e-12)
    np.testing.assert_allclose(R_wb[-1].T @ R_wb[-1], np.eye(3), atol=1e-12)
    assert np.all(np.linalg.det(R_wb) > 0)
    # smooth: the rate changes little from one sample to the next, and it turns a real amount
    assert np.max(np.abs(np.diff(omega_b, axis=0))) < 10 * dt
    assert 0.05 < np.max(np.linalg.norm(omega_b, axis=1)) < 2.0


def test_accelerometer_at_rest_reads_gravity_in_the_body_frame():
    rng = np.random.default_rng(0)
    for _ in range(5):
        R = Exp(rng.normal(size=3))
        measured, bias = simulate_accelerometer(np.repeat(R[None], 2000, axis=0), seed=2)
        up_b = R.T @ [0.0, 0.0, 1.0]
        mean = measured.mean(axis=0)
        assert np.linalg.norm(mean - GRAVITY * up_b) < 0.02  # bias of a few mg, noise averaged out
        direction = mean / np.linalg.norm(mean)
        assert np.degrees(np.arccos(np.clip(direction @ up_b, -1, 1))) < 0.1


def test_accelerometer_adds_the_world_acceleration():
    R_wb, _ = smooth_motion(1.0, seed=4)
    accel_w = np.random.default_rng(1).normal(size=(len(R_wb), 3))
    quiet = ImuModel("noiseless", "none", 200.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    measured, _ = simulate_accelerometer(R_wb, model=quiet, accel_w=accel_w)
    for k in (0, 50, 200):
        np.testing.assert_allclose(measured[k], R_wb[k].T @ (accel_w[k] + [0, 0, GRAVITY]), atol=1e-12)


def test_seeds_reproduce_and_differ():
    a, b = smooth_motion(2.0, seed=1), smooth_motion(2.0, seed=1)
    assert all(np.array_equal(x, y) for x, y in zip(a, b))
    assert not np.array_equal(smooth_motion(2.0, seed=2)[1], a[1])
    omega_b = a[1]
    g1, g2 = simulate_gyro(omega_b, seed=9), simulate_gyro(omega_b, seed=9)
    assert all(np.array_equal(x, y) for x, y in zip(g1, g2))
    assert not np.array_equal(simulate_gyro(omega_b, seed=10)[0], g1[0])
    f1, f2 = simulate_accelerometer(a[0], seed=9), simulate_accelerometer(a[0], seed=9)
    assert all(np.array_equal(x, y) for x, y in zip(f1, f2))
    # the two sensors' noises are independent even with the same seed
    gyro_noise = (g1[0] - omega_b - g1[1])[:, 0]
    accel_noise = (f1[0] - f1[1])[:-1, 0] - np.einsum("kji,j->ki", a[0], [0, 0, GRAVITY])[:-1, 0]
    assert abs(np.corrcoef(gyro_noise, accel_noise)[0, 1]) < 0.2


def test_inputs_left_unchanged():
    R_wb, omega_b = smooth_motion(1.0, seed=0)
    accel_w = np.ones((len(R_wb), 3))
    copies = [R_wb.copy(), omega_b.copy(), accel_w.copy()]
    simulate_gyro(omega_b)
    simulate_accelerometer(R_wb, accel_w=accel_w)
    for before, after in zip(copies, [R_wb, omega_b, accel_w]):
        assert np.array_equal(before, after)
    simulate_gyro(omega_b.tolist())  # lists are accepted too


def test_imports_numpy_only_and_coursekit_does_not_import_it():
    code = (
        "import sys, coursekit; assert 'coursekit.imu' not in sys.modules; "
        "import coursekit.imu; assert 'scipy' not in sys.modules, 'scipy imported'"
    )
    import coursekit

    root = str(__import__("pathlib").Path(coursekit.__file__).parents[1])
    subprocess.run([sys.executable, "-c", code], check=True, cwd=root)
