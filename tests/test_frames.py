"""pandas in and out (issue 14): DataFrames and Series through diagnose,
fit_weights, fit and the regressor; datetime time axes as seconds; CSV
files as measurement software writes them."""

import gzip

import numpy as np
import pandas as pd
import pytest

from hystcomp import PI
from hystcomp.diagnose import diagnose, load_csv
from hystcomp.diagnose.record import Record
from hystcomp.identify import fit, fit_weights

V = 3 * np.sin(np.linspace(0, 20, 3000))
TRUE = PI([1.0, 2.0], [0.5, 0.2], p0=1.0)
Y = TRUE.simulate(V) + 0.1
IDX = pd.date_range("2024-05-01 12:00", periods=V.size, freq="10ms", name="when")


# --------------------------------------------------------------------------
# time axes
# --------------------------------------------------------------------------
@pytest.mark.parametrize("make", [
    lambda s: s,                                              # pandas datetime Series
    lambda s: s.to_numpy(),                                   # numpy datetime64[ns]
    lambda s: s.dt.tz_localize("Europe/Berlin"),              # time-zone aware
    lambda s: s - s.iloc[0] + pd.Timedelta("3 s"),            # timedelta (from its first sample)
    lambda s: pd.DatetimeIndex(s),
])
def test_datetime_time_axis_is_seconds_from_the_first_sample(make):
    stamps = pd.Series(pd.date_range("2024-05-01", periods=200, freq="25ms"))
    rec = Record(make(stamps), np.sin(0.1 * np.arange(200)), np.cos(0.1 * np.arange(200)), 0.3)
    # seconds, never nanoseconds: 0, 0.025, ... (exact up to float rounding)
    np.testing.assert_allclose(rec.t, 0.025 * np.arange(200), rtol=0, atol=1e-12)
    assert rec.dt == pytest.approx(0.025)


def test_missing_time_is_named():
    stamps = pd.Series(pd.date_range("2024-05-01", periods=200, freq="25ms"))
    stamps[7] = pd.NaT
    with pytest.raises(ValueError, match=r"t holds a missing time \(NaT\) at sample index 7"):
        Record(stamps, np.sin(0.1 * np.arange(200)), np.cos(0.1 * np.arange(200)), 0.3)


# --------------------------------------------------------------------------
# diagnose
# --------------------------------------------------------------------------
def test_a_dataframe_through_diagnose_equals_the_arrays():
    from hystcomp.datasets import hidden_effect_data

    d = hidden_effect_data("drift", seed=3, dt=0.01)
    df = pd.DataFrame({"time": pd.Timestamp("2024-05-01") + pd.to_timedelta(d.t, unit="s"),
                       "volt": d.v, "um": d.y})
    a = diagnose(d.t - d.t[0], d.v, d.y, effects=["drift", "creep"], progress=False)
    b = diagnose(df, time="time", input="volt", output="um", effects=["drift", "creep"], progress=False)
    assert a.effects == b.effects == ["drift"]
    # the same record: the same held-out RMS (up to the datetime's microsecond rounding)
    assert b.rms_heldout == pytest.approx(a.rms_heldout, rel=1e-6)
    # the time as the index, and Series instead of a frame
    c = diagnose(df.set_index("time"), time="time", input="volt", output="um", effects=["drift"],
                 progress=False)
    assert c.effects == ["drift"]
    e = diagnose(df["time"], df["volt"], df["um"], effects=["drift"], progress=False)
    assert e.rms_heldout == pytest.approx(a.rms_heldout, rel=1e-6)


def test_diagnose_frame_errors_name_the_column():
    df = pd.DataFrame({"t": 0.01 * np.arange(300), "v": np.sin(0.05 * np.arange(300)),
                       "y": np.sin(0.05 * np.arange(300))})
    with pytest.raises(ValueError, match=r"output is 'um' .* no such column \(columns: t, v, y\)"):
        diagnose(df, output="um", progress=False)
    with pytest.raises(TypeError, match="v and y must not be given"):
        diagnose(df, df.v, df.y, progress=False)
    with pytest.raises(TypeError, match="input is 'v' but that column holds"):
        diagnose(df.assign(v=["a"] * 300), progress=False)
    with pytest.raises(TypeError, match="v and y are missing"):
        diagnose(df.t.to_numpy(), progress=False)


# --------------------------------------------------------------------------
# fit_weights, fit, predictions keep the index
# --------------------------------------------------------------------------
def test_fit_weights_frame_equals_arrays_and_keeps_the_index():
    df = pd.DataFrame({"volt": V, "um": Y}, index=IDX)
    a = fit_weights(V, Y, thresholds=[1.0, 2.0], model="pi")
    b = fit_weights(df, thresholds=[1.0, 2.0], model="pi", input="volt", output="um")
    np.testing.assert_array_equal(a.weights, b.weights)
    assert isinstance(a.residuals, np.ndarray)            # arrays in, arrays out (unchanged)
    assert isinstance(b.residuals, pd.Series) and b.residuals.index.equals(IDX)
    np.testing.assert_array_equal(b.residuals.to_numpy(), a.residuals)
    pred = b.predict(df["volt"])
    assert isinstance(pred, pd.Series) and pred.index.equals(IDX)
    np.testing.assert_allclose(pred.to_numpy(), Y, atol=1e-6)
    assert isinstance(b.predict(V), np.ndarray)
    # Series in: the index of the Series
    c = fit_weights(df["volt"], df["um"], thresholds=[1.0, 2.0], model="pi")
    assert c.residuals.index.equals(IDX)


def test_fit_weights_list_of_frames_is_several_records():
    df = pd.DataFrame({"v": V, "y": Y}, index=IDX)
    res = fit_weights([df.iloc[:1500], df.iloc[1500:]], thresholds=[1.0, 2.0], model="pi")
    assert [r.index.equals(i) for r, i in zip(res.residuals, (IDX[:1500], IDX[1500:]))] == [True, True]
    with pytest.raises(TypeError, match="y must not be given"):
        fit_weights([df, df], [Y, Y], thresholds=[1.0, 2.0], model="pi")


def test_fit_weights_frame_errors():
    df = pd.DataFrame({"v": V, "y": Y})
    with pytest.raises(ValueError, match=r"input is 'volt' but the DataFrame v has no such column"):
        fit_weights(df, input="volt")
    with pytest.raises(TypeError, match="y is missing"):
        fit_weights(V)


def test_fit_with_a_frame_keeps_the_index():
    from hystcomp import MGPI
    from hystcomp.envelopes import Tanh

    y = MGPI([1.0, 2.0], [0.5, 0.2], 1.0, envelope=Tanh(1 / 0.3, 0.3)).simulate(V)
    df = pd.DataFrame({"v": V, "y": y}, index=IDX)
    res = fit(df, thresholds=[1.0, 2.0])
    assert round(res.envelope.b, 4) == 0.3
    assert isinstance(res.residuals, pd.Series) and res.residuals.index.equals(IDX)


# --------------------------------------------------------------------------
# CSV through pandas
# --------------------------------------------------------------------------
ROWS = [(0.01 * k, np.sin(0.1 * k), np.cos(0.1 * k)) for k in range(150)]


def _body(sep=",", dec="."):
    return "\n".join(sep.join(f"{x:.6g}".replace(".", dec) for x in r) for r in ROWS) + "\n"


@pytest.mark.parametrize("name, text", [
    ("plain.csv", "t,v,y\n" + _body()),
    ("spaces.txt", "t v y\n" + _body(" ")),
    ("tabs.tsv", "t\tv\ty\n" + _body("\t")),
    ("comments_units.csv", "# rig 3, amplifier 20 V/V\n\n# 2024-05-01\nt,v,y\ns,V,um\n" + _body()),
    ("european.csv", "t;v;y\n" + _body(";", ",")),
    ("padded.csv", "t, v, y\n" + _body(", ")),
    ("iso_times.csv", "t,v,y\n" + "\n".join(
        f"2024-05-01T12:00:{r[0]:09.6f},{r[1]:.6g},{r[2]:.6g}" for r in ROWS) + "\n"),
])
def test_csv_layouts(tmp_path, name, text):
    path = tmp_path / name
    path.write_text(text)
    t, v, y = load_csv(path)
    np.testing.assert_allclose(t, [r[0] for r in ROWS], atol=1e-9)
    # six significant digits in the file
    np.testing.assert_allclose(v, [r[1] for r in ROWS], atol=1e-6)
    np.testing.assert_allclose(y, [r[2] for r in ROWS], atol=1e-6)


def test_gzip_csv_and_bom(tmp_path):
    gz = tmp_path / "rec.csv.gz"
    with gzip.open(gz, "wb") as fh:
        fh.write(b"\xef\xbb\xbft,v,y\n" + _body().encode())
    t, v, _ = load_csv(gz)
    assert t.size == 150 and v[5] == pytest.approx(np.sin(0.5), abs=1e-6)


def test_csv_errors_name_the_file_line_and_column(tmp_path):
    lines = ["t,v,y", "s,V,um"] + [",".join(f"{x:.6g}" for x in r) for r in ROWS]
    lines[40] = "0.38,abc,1.0"          # file line 41
    path = tmp_path / "bad.csv"
    path.write_text("\n".join(lines) + "\n")
    with pytest.raises(ValueError, match=r"bad\.csv line 41: column 'v' holds 'abc', not a number"):
        load_csv(path)
    lines[40] = "0.38,inf,1.0"
    path.write_text("\n".join(lines) + "\n")
    with pytest.raises(ValueError, match=r"line 41: column 'v' holds inf; expected a finite number"):
        load_csv(path)
    path.write_text("t,v,y,t\n" + _body())
    with pytest.raises(ValueError, match="repeats the column name"):
        load_csv(path)
    gz = tmp_path / "bad.csv.gz"
    gz.write_bytes(b"not gzip at all")
    with pytest.raises(ValueError, match=r"bad\.csv\.gz"):
        load_csv(gz)
