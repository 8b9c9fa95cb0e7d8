"""The landscape from Python against the C++ tests' values: A_−, A_*, J(A_−) = 4.9757…, the
minima at A = 1 and 11, and the paper's seven zones of the chamber map; what the command line refuses,
refused in its words before any work."""

import subprocess

import numpy as np
import pytest
import rotorsweep
from conftest import python_words


def test_thresholds_and_jump_friction():
    assert rotorsweep.A_minus == pytest.approx(4.634583466980286, rel=1e-14)
    assert rotorsweep.A_star == pytest.approx(8.778365775883558, rel=1e-15)
    J = rotorsweep.jump_friction([rotorsweep.A_minus, 6.0, rotorsweep.A_star, 3.0, 10.0])
    assert J[0] == pytest.approx(4.975766521411717, rel=1e-13)
    assert 0 < J[1] < J[0]
    assert abs(J[2]) < 1e-13
    assert np.isnan(J[3]) and np.isnan(J[4])
    events = rotorsweep.jump_events(6.0)
    assert events["J"] == J[1]


def test_critical_points_at_A_1_and_11():
    for tau in np.linspace(0, np.pi / 2, 7):
        large = rotorsweep.critical_points(11.0, tau)
        assert list(large["type"]).count("minimum") == 1
        assert large["alignment"][large["type"] == "minimum"][0] == "strict_fm"
        small = rotorsweep.critical_points(1.0, tau)
        minima = small["type"] == "minimum"
        assert minima.sum() == 4
        assert sorted(small["alignment"][minima]) == ["afm_like", "afm_like", "strict_fm", "strict_fm"]
        counts = {t: list(small["type"]).count(t) for t in ("minimum", "saddle", "maximum")}
        assert counts["minimum"] - counts["saddle"] + counts["maximum"] == 0  # Euler characteristic
        assert small["even"].dtype == np.float64 and small["even"].flags["OWNDATA"] is False


def test_chamber_map_has_the_papers_seven_zones():
    ds = rotorsweep.chamber_map(A_min=0.0, A_max=12.0, A_cells=120, tau_cells=90)
    assert dict(ds.minima.sizes) == {"A": 120, "tau": 90}
    zone = ds.zone.values
    sizes = np.bincount(zone[zone >= 0])
    assert (sizes >= 10).sum() == 7
    assert int((ds.minima - ds.saddles + ds.maxima).max()) == 0
    assert int(ds.minima.isel(A=119, tau=45)) == 1
    assert int(ds.by_type_and_class.sel(type="minimum", alignment="strict_fm").isel(A=119, tau=45)) == 1


def test_curves():
    curve = rotorsweep.bifurcation_curve("off_diagonal_minus", 200)
    assert np.nanmin(curve["A"]) == pytest.approx(rotorsweep.A_minus, rel=1e-3)
    with pytest.raises(ValueError, match="alignment"):
        rotorsweep.bifurcation_curve("no_such_curve")


def test_coupling_tables_landscape():
    k = rotorsweep.two_angle_coefficients(4)
    np.testing.assert_allclose(k, (2.1154969038, 2.3926076195, 2.1015765433), rtol=1e-9)
    assert rotorsweep.two_angle_coefficients("all", rows=20)[0] > k[0]
    with pytest.raises(ValueError):
        rotorsweep.two_angle_coefficients("all")
    lo, hi = rotorsweep.landscape.cp_interval()
    assert (lo, hi) == (rotorsweep.A_minus, rotorsweep.A_star)
    A = np.linspace(lo + 0.01, hi - 0.01, 7)
    J, rho = rotorsweep.quasi_static_friction(A)
    np.testing.assert_allclose(J, rotorsweep.jump_friction(A), atol=1e-7)
    assert np.all((rho > 0.5) & (rho < 1))
    lo4, hi4 = rotorsweep.landscape.cp_interval(k)
    assert lo4 < lo and hi4 > hi + 4
    J4, _ = rotorsweep.quasi_static_friction([lo4 - 0.5, 10.0, hi4 + 0.5], k)
    assert J4[0] == 0 and J4[1] > 1 and J4[2] == 0


def test_refused_as_the_command_line_refuses_before_any_work(executable, tmp_path):
    """The command line's bounds as ValueError, and a map too large for memory in its words."""
    with pytest.raises(ValueError, match="2 <= A_cells, tau_cells <= 100000"):
        rotorsweep.chamber_map(A_cells=1_000_000)
    with pytest.raises(ValueError, match="2 <= count <= 10000000"):
        rotorsweep.bifurcation_curve("alignment", count=10**9)
    cli = subprocess.run([executable, "landscape", "chambers", "--A-cells", "100000", "--tau-cells", "100000",
                          "-q", "-o", str(tmp_path / "c.h5")], capture_output=True, text=True)
    assert cli.returncode == 2 and "landscape chambers needs about" in cli.stderr, cli.stderr
    with pytest.raises(ValueError) as raised:
        rotorsweep.chamber_map(A_cells=100_000, tau_cells=100_000)
    assert str(raised.value) == python_words(cli.stderr)
    assert not (tmp_path / "c.h5").exists()


def test_coefficients_without_a_cp_window_and_a_range_out_of_bounds_are_value_errors():
    """As `landscape --coefficients 0,0,0` and `couplings --range 0` are exit 2 (no hang, no NaN)."""
    for call in (lambda: rotorsweep.quasi_static_friction([5.0], (0, 0, 0)),
                 lambda: rotorsweep.jump_friction(5.0, (0, 0, 0))):
        with pytest.raises(ValueError, match="give no CP window"):
            call()
    with pytest.raises(ValueError, match="range must be 1"):
        rotorsweep.two_angle_coefficients(0)
