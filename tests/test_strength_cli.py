"""CLI tests: chaindrive contact / tooth-strength / fretting / bolts."""

from __future__ import annotations

import json

import pytest

from chaindrive.cli import main


def _json(capsys, argv):
    assert main(argv) == 0
    return json.loads(capsys.readouterr().out)


def test_contact_json_si(capsys):
    d = _json(capsys, ["contact", "--chain", "16B", "--seat-radius", "68.7 mm", "--contact", "convex",
                       "--load", "5 kN", "--skew", "50 arcmin", "--json"])
    assert d["pitch"] == pytest.approx(0.0254)
    assert d["load_factor"] == pytest.approx(2.2675)
    assert d["stress_unskewed"] == pytest.approx(1.23197e9 * (17 / 17.02) ** 0.5, rel=1e-5)  # L_p = b1
    assert d["max_skew"] == pytest.approx(50 * 3.141592653589793 / 10800)


def test_contact_flank_from_teeth(capsys):
    # ISO 606:2015 5.4.2: r_e,min = 0.12 d1 (z + 2) = 0.12 * 15.88 * 21 = 40.018 mm
    d = _json(capsys, ["contact", "--chain", "16B", "--contact", "convex", "--teeth", "19", "--load", "5 kN", "--json"])
    assert d["seat_radius"] == pytest.approx(40.0176e-3, rel=1e-6)
    assert main(["contact", "--chain", "16B", "--contact", "convex", "--load", "5 kN"]) == 2
    assert "needs --seat-radius" in capsys.readouterr().err


def test_contact_from_measurement_and_text(capsys):
    d = _json(capsys, ["contact", "--pitch", "19.05 mm", "--roller-diameter", "12.07 mm", "--seat-radius", "40 mm",
                       "--contact", "convex", "--length", "11.7 mm", "--load", "3 kN", "--skew-dh", "0.185 mm",
                       "--skew-base", "12.7 mm", "--json"])
    assert d["gamma"] == 0.0016 and d["max_skew"] > 0
    assert main(["contact", "--chain", "16B", "--seat-radius", "68.7 mm", "--contact", "convex", "--load", "5 kN"]) == 0
    out = capsys.readouterr().out
    assert "Garshniev & Maksymovych" in out and "MPa" in out


@pytest.mark.parametrize(
    "argv,pattern",
    [
        (["contact", "--chain", "16B", "--load", "-5 kN"], "load must be positive"),
        (["contact", "--chain", "16B", "--load", "5 kN", "--skew", "10 arcmin", "--skew-dh", "1 mm"], "either --skew"),
        (["contact", "--chain", "16B", "--load", "5 kN", "--skew-dh", "1 mm"], "--skew-base"),
        (["contact", "--load", "5 kN", "--length", "1 mm"], "--roller-diameter is needed"),
        (["contact", "--pitch", "38.1 mm", "--roller-diameter", "25.4 mm", "--seat-radius", "80 mm", "--contact",
          "convex", "--length", "25 mm", "--load", "5 kN", "--skew", "20 arcmin", "--gamma-outside", "raise"],
         r"outside the gamma table of Garshniev & Maksymovych \(12.7 ... 25.4 mm\)"),
        (["contact", "--chain", "16B", "--load", "5 kg"], "load: '5 kg' has units"),
        (["tooth-strength", "--weight", "60 kN", "--rims", "3", "--pitch", "170 mm", "--teeth", "13",
          "--pin-radius", "25 mm", "--tooth-width", "50 mm"], "rims must be 1 or 2"),
        (["fretting", "--load", "5 kN"], "give --chain or all of"),
        (["fretting", "--chain", "16B-3", "--load", "5 kN", "--k1", "1e12 s/m"], "give both --k1"),
        (["bolts", "--bolt-circle-radius", "250 mm", "--bolts", "12"], "give --torque"),
        (["bolts", "--torque", "7 kN*m", "--bolt-circle-radius", "250 mm", "--bolts", "12", "--joint", "glue"],
         "joint must be 'fitted' or 'friction'"),
    ],
)
def test_bad_input_exit_2(capsys, argv, pattern):
    import re

    assert main(argv) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err[-1].startswith("error: ") and re.search(pattern, err[-1])


def test_tooth_strength(capsys):
    base = ["tooth-strength", "--weight", "60 kN", "--rims", "2", "--pitch", "170 mm", "--teeth", "13",
            "--pin-radius", "25 mm", "--link", "cast", "--tooth-width", "50 mm", "--hardness", "52"]
    d = _json(capsys, base + ["--allowable-contact", "1200 MPa", "--json"])
    assert d["design_force"] == pytest.approx(19500.0)
    assert d["contact_safety"] == pytest.approx(1200e6 / d["contact_stress"])
    assert main(base + ["--allowable-contact", "500 MPa"]) == 1  # check fails
    assert "passes" in capsys.readouterr().out


def test_fretting_cli(capsys):
    d = _json(capsys, ["fretting", "--chain", "16B-3", "--load", "5 kN", "--k1", "1e12 s/m", "--k2", "2.9e-7 s/N", "--json"])
    assert d["slip_ratio"] == pytest.approx(39.99, rel=1e-3)
    assert d["fretting"]["life_ratio"] > 1
    assert d["with_intermediate_plates"]["slip_amplitude"] < d["without_intermediate_plates"]["slip_amplitude"]
    assert main(["fretting", "--pin-diameter", "8.28 mm", "--transverse-pitch", "31.88 mm", "--strands", "2",
                 "--inner-width", "17.02 mm", "--load", "5 kN"]) == 0
    assert "slip ratio" in capsys.readouterr().out


def test_bolts_cli(capsys):
    d = _json(capsys, ["bolts", "--force", "19.5 kN", "--pitch-radius", "355 mm", "--bolt-circle-radius", "250 mm",
                       "--bolts", "12", "--joint", "friction", "--diameter", "16 mm", "--thread-pitch", "2 mm",
                       "--yield-strength", "640 MPa", "--json"])
    assert d["torque"] == pytest.approx(19500 * 0.355)
    assert d["required_preload"] == pytest.approx(1.25 * d["bolt_force"] / 0.15)
    d = _json(capsys, ["bolts", "--torque", "6.9 kN*m", "--bolt-circle-radius", "250 mm", "--bolts", "12",
                       "--shank-diameter", "17 mm", "--json"])
    assert d["bolt_force"] == pytest.approx(2300.0)
    assert main(["bolts", "--torque", "6.9 kN*m", "--bolt-circle-radius", "250 mm", "--bolts", "12",
                 "--shank-diameter", "17 mm", "--allowable-shear", "5 MPa"]) == 1


@pytest.mark.parametrize(
    "cmd,needle",
    [("contact", "Garshniev & Maksymovych"), ("tooth-strength", "Sharipov"), ("fretting", "Vikulov"), ("bolts", "VDI 2230")],
)
def test_help_names_sources(capsys, cmd, needle):
    assert main([cmd, "--help"]) == 0
    assert needle in capsys.readouterr().out
