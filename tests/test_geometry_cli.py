"""CLI: chaindrive sprocket / pocket-wheel / track-wheel."""

from __future__ import annotations

import json

import pytest

from chaindrive.cli import main

ezdxf = pytest.importorskip("ezdxf")


def _json(capsys, argv):
    assert main(argv) == 0
    return json.loads(capsys.readouterr().out)


def test_sprocket_json_from_catalogue(capsys, tmp_path):
    dxf, svg = tmp_path / "s.dxf", tmp_path / "s.svg"
    out = _json(capsys, ["sprocket", "--chain", "16B", "--teeth", "19", "--json", "--dxf", str(dxf), "--svg", str(svg)])
    assert out["pitch_diameter"] == pytest.approx(0.0254 / 0.16459459028073403, rel=1e-12)
    assert out["tip_diameter_max"] == pytest.approx(0.17018855905274619, rel=1e-12)
    assert out["tooth_width"] == pytest.approx(0.95 * 0.01702)
    assert out["outline"]["form"] == "min"
    assert "ISO 606:2015" in out["sources"]["seating_angle"]
    assert not ezdxf.readfile(dxf).audit().has_errors
    assert svg.read_text().startswith("<?xml")


def test_sprocket_explicit_dimensions_and_ansi(capsys):
    out = _json(capsys, ["sprocket", "--pitch", "1 in", "--roller-diameter", "0.625 in", "--teeth", "28",
                         "--method", "ansi", "--json"])
    assert out["ansi"]["topping_radius"] / 0.0254 == pytest.approx(0.5114, abs=6e-5)
    assert out["outline"]["form"] is None
    assert main(["sprocket", "--pitch", "25.4 mm", "--roller-diameter", "15.88 mm", "--teeth", "19",
                 "--form", "max", "--inner-width", "17.02 mm", "--plate-height", "21.08 mm"]) == 0
    text = capsys.readouterr().out
    assert "ISO 606:2015 5.4.2" in text and "max hub diameter dg" in text and "129.531 mm" in text


@pytest.mark.parametrize(
    "argv,message",
    [
        (["sprocket", "--chain", "16B", "--teeth", "5"], "teeth must be a whole number >= 9"),
        (["sprocket", "--chain", "18x64", "--teeth", "19"], "not a roller chain"),
        (["sprocket", "--teeth", "19"], "give --chain NAME, or both --pitch and --roller-diameter"),
        (["sprocket", "--chain", "16B", "--teeth", "19", "--form", "mid"], "form must be 'min'"),
        (["sprocket", "--chain", "16B", "--teeth", "19", "--tip-diameter", "200 mm"], "--tip-diameter must lie in"),
        (["sprocket", "--chain", "16B", "--teeth", "19", "--method", "din"], "unknown method 'din'"),
        (["pocket-wheel", "--teeth", "8"], "give --chain NAME, or both --pitch and --bar-diameter"),
        (["pocket-wheel", "--chain", "16B", "--teeth", "8"], "no bar_diameter"),
        (["track-wheel", "--pitch", "170 mm", "--teeth", "13", "--pin-radius", "25 mm", "--tip-factor", "0.9"],
         r"--tip-factor must lie in [0.2, 0.5] for built-up links"),
        (["track-wheel", "--pitch", "170 mm", "--teeth", "13", "--pin-radius", "25 mm", "--link", "cast",
          "--root-factor", "1.5"], "--root-factor must lie in [1.1, 1.3]"),
        (["track-wheel", "--pitch", "170 mm", "--teeth", "13", "--pin-radius", "3 kg"],
         "--pin-radius: '3 kg' has units of [mass]"),
        # the cases: a TypeError, an OverflowError and a 74.5 GiB MemoryError before
        (["pocket-wheel", "--chain", "18x64", "--teeth", "8", "--inner-width", "-0"],
         'error: --inner-width: give a unit, e.g. "-0 mm" or "-0 m"'),
        (["pocket-wheel", "--chain", "18x64", "--teeth", "8", "--inner-width", "-0 mm"],
         "--inner-width must be positive"),
        (["track-wheel", "--pitch", "2**1000", "--teeth", "13", "--pin-radius", "25 mm"],
         "--pitch: cannot read '2**1000' as a quantity"),
        (["track-wheel", "--pitch", "170 mm", "--teeth", "10000000000", "--pin-radius", "25 mm"],
         "teeth must be a whole number in [3, 10000]"),
        (["sprocket", "--chain", "16B", "--teeth", "19", "--inner-width", "17"], "--inner-width: give a unit"),
    ],
)
def test_error_paths(capsys, argv, message):
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert message in err and "Traceback" not in err and "internal error" not in err


def test_pocket_wheel(capsys, tmp_path):
    svg = tmp_path / "p.svg"
    out = _json(capsys, ["pocket-wheel", "--chain", "18x64", "--teeth", "8", "--json", "--svg", str(svg)])
    assert out["pitch_radius"] == pytest.approx(0.1642830686421091, rel=1e-12)
    assert len(out["hinge_angles"]) == 16
    assert svg.exists()
    out = _json(capsys, ["pocket-wheel", "--pitch", "64 mm", "--bar-diameter", "18 mm", "--teeth", "8",
                         "--clearance", "0.5 mm", "--inner-width", "21 mm", "--json"])
    assert out["clearance"] == pytest.approx(0.5e-3)
    assert main(["pocket-wheel", "--chain", "18x64", "--teeth", "8"]) == 0
    assert "Dolipiński et al. eq. (6)" in capsys.readouterr().out


def test_track_wheel(capsys, tmp_path):
    dxf = tmp_path / "t.dxf"
    out = _json(capsys, ["track-wheel", "--pitch", "170 mm", "--teeth", "13", "--pin-radius", "25 mm",
                         "--link", "cast", "--json", "--dxf", str(dxf)])
    assert out["tip_radius_range"] == pytest.approx([out["pitch_radius"] + 0.02, out["pitch_radius"] + 0.03])
    assert out["root_radius"] == pytest.approx(out["pitch_radius"] - 1.2 * 0.025)
    assert not ezdxf.readfile(dxf).audit().has_errors
    assert main(["track-wheel", "--pitch", "0.17 m", "--teeth", "13", "--pin-radius", "0.025 m"]) == 0
    text = capsys.readouterr().out
    assert "Sharipov" in text and "root radius R_root" in text
    assert not any("\u0400" <= ch <= "\u04ff" for ch in text)  # Latin symbols, no Cyrillic


@pytest.mark.parametrize("cmd,words", [("sprocket", ["ISO 606", "ASME B29.1", "5.5"]),
                                       ("pocket-wheel", ["Dolipiński et al.", "DIN 22252"]),
                                       ("track-wheel", ["Sharipov", "1.1...1.3"])])
def test_help_names_sources(capsys, cmd, words):
    assert main([cmd, "--help"]) == 0
    text = " ".join(capsys.readouterr().out.split())
    for w in words:
        assert w in text
