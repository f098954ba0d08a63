# pycinema's .h5 images (docs/formats.md, "pycinema's HDF5 images"), both ways:
# a Spec D database written with h5py exactly as pycinema's
# CinemaDatabaseWriter.writeH5 writes one is shaded by `darkroom run`, and the
# .h5 products Darkroom writes (CinemaWriter format: h5, DatabaseWriter
# format="h5") are read with h5py as pycinema's ImageReader reads them.
import os
import subprocess

import numpy as np
import pytest

import darkroom as dr

h5py = pytest.importorskip("h5py")

H, W = 4, 6


def pycinema_write_h5(path, channels, meta):
    """As pycinema's CinemaDatabaseWriter.writeH5: every channel and every
    array in gzip 9; text as a one-element numpy 'S10' array; other values as
    they are (a Python float becomes a scalar dataset)."""
    with h5py.File(path, "w") as f:
        group = f.create_group("channels")
        for k, v in channels.items():
            group.create_dataset(k, data=v, compression="gzip", compression_opts=9)
        group = f.create_group("meta")
        for k, v in meta.items():
            if isinstance(v, np.ndarray) and v.size > 1:
                group.create_dataset(k, data=v, compression="gzip", compression_opts=9)
            elif isinstance(v, str):
                group.create_dataset(k, data=np.array([v], dtype="S10"))
            else:
                group.create_dataset(k, data=v)


def pycinema_read_h5(path):
    """As pycinema's ImageReader reads an .h5: every dataset of channels and
    meta into dicts; a one-element 'S10' array becomes its text."""
    image = {"channels": {}, "meta": {}}
    with h5py.File(path, "r") as f:
        for g in ("channels", "meta"):
            group = f.get(g)
            assert group is not None, f"{path}: no group {g}"
            for k in group.keys():
                data = np.array(group.get(k))
                if data.dtype == "|S10" and len(data) == 1:
                    data = data[0].decode("UTF-8")
                image[g][k] = data
    return image


def temperature_field(time):
    """0 in the top two rows, 1 in the bottom two: up and down are told apart."""
    t = np.zeros((H, W), np.float32)
    t[H // 2:, :] = 1.0
    return t + np.float32(0) * time


def depth_field():
    """pycinema's depth: normalised to [0, 1], 1.0 the background (top-left pixel)."""
    d = np.tile(np.linspace(0.2, 0.7, W, dtype=np.float32), (H, 1))
    d[0, 0] = 1.0
    return d


@pytest.fixture
def pycinema_db(tmp_path):
    folder = tmp_path / "pycinema.cdb"
    folder.mkdir()
    rows = ["time,FILE"]
    for i, time in enumerate((1.0, 2.0)):
        name = f"{i}.h5"
        rgba = np.zeros((H, W, 4), np.uint8)
        rgba[..., 0] = 255
        rgba[..., 3] = 255
        pycinema_write_h5(folder / name,
                          {"depth": depth_field(), "temperature": temperature_field(time), "rgba": rgba},
                          {"time": time, "label": "pycinema"})
        rows.append(f"{time},{name}")
    (folder / "data.csv").write_text("\n".join(rows) + "\n")
    return folder


def test_a_pycinema_database_reads_with_its_rows_top_to_bottom(pycinema_db):
    img = dr.Database(str(pycinema_db)).read(where="time=2")
    t = img["temperature"]
    assert t.shape == (H, W) and t.dtype == np.float32
    np.testing.assert_array_equal(t, temperature_field(2.0))  # row 0 is the top row
    z = img["Z"]
    assert np.isinf(z[0, 0]) and np.all(np.isfinite(z.ravel()[1:]))
    assert z[1, 0] < z[1, W - 1]  # depth kept in order (normalised: no CameraNearFar in pycinema's meta)
    assert img["R"][2, 3] == pytest.approx(1.0) and img["G"][2, 3] == 0.0 and img["A"][2, 3] == 1.0


def run_darkroom(args):
    runner = os.environ.get("DARKROOM_RUNNER")
    if not runner:
        pytest.skip("DARKROOM_RUNNER (the darkroom executable) is not set; ctest sets it")
    return subprocess.run([runner, *args], capture_output=True, text=True, timeout=300)


SHADE = """darkroom: 1
nodes:
  read: {type: CinemaReader, parameters: {database: %s}}
  colour:
    type: ColorMapping
    parameters: {channel: temperature, colormap: %s, range: manual, minimum: 0, maximum: 1}
  write: {type: CinemaWriter, parameters: {database: shaded.cdb, format: h5}}
edges:
  - read.image -> colour.image
  - colour.image -> write.image
  - read.row -> write.row
"""


def test_darkroom_shades_a_pycinema_database_into_h5_that_pycinema_reads(pycinema_db, tmp_path):
    # A map from red (value 0) to blue (value 1): the ends are exact whatever the interpolation.
    cmap = tmp_path / "red-blue.json"
    cmap.write_text('[{"Name": "red-blue", "ColorSpace": "RGB", "RGBPoints": [0, 1, 0, 0, 1, 0, 0, 1]}]')
    pipeline = tmp_path / "shade.yaml"
    pipeline.write_text(SHADE % (pycinema_db, cmap))
    done = run_darkroom(["-q", "run", str(pipeline), "--foreach", "read", "-o", str(tmp_path / "out")])
    assert done.returncode == 0, done.stderr
    shaded = tmp_path / "out" / "shaded.cdb"
    rows = (shaded / "data.csv").read_text().splitlines()
    assert rows[0] == "time,FILE" and len(rows) == 3
    product = shaded / rows[2].split(",")[1]
    assert product.suffix == ".h5"

    image = pycinema_read_h5(product)
    assert set(image["channels"]) == {"rgba", "depth"}
    rgba = image["channels"]["rgba"]
    assert rgba.shape == (H, W, 4) and rgba.dtype == np.uint8
    np.testing.assert_array_equal(rgba[0, 1], [255, 0, 0, 255])      # top rows: value 0, red
    np.testing.assert_array_equal(rgba[H - 1, 0], [0, 0, 255, 255])  # bottom rows: value 1, blue
    np.testing.assert_array_equal(rgba[0, 0], [0, 0, 0, 0])          # the background: transparent
    depth = image["channels"]["depth"]
    assert depth.shape == (H, W) and depth.dtype == np.float32
    assert depth[0, 0] == 1.0 and np.all((depth.ravel()[1:] >= 0) & (depth.ravel()[1:] < 1))
    assert np.all(np.diff(depth[1]) > 0)  # farther to the right, as in the source
    meta = image["meta"]
    assert meta["time"] == 2.0 and meta["time"].shape == ()  # the row, as pycinema keeps it
    np.testing.assert_array_equal(meta["resolution"], [W, H])
    assert meta["resolution"].dtype == np.float32


def test_darkroom_h5_floats_read_with_h5py_exactly_and_top_row_first(tmp_path):
    value = np.arange(H * W, dtype=np.float32).reshape(H, W) * 0.25 - 1.5
    ids = np.arange(H * W, dtype=np.uint32).reshape(H, W) + 7
    path = str(tmp_path / "made.cdb")
    with dr.DatabaseWriter(path, ["time", "kind"], format="h5") as w:
        w.add({"time": 0.5, "kind": "a"}, dr.Image.from_arrays({"value": value, "id": ids}))
    files = [f for f in os.listdir(path) if f.endswith(".h5")]
    assert len(files) == 1
    image = pycinema_read_h5(os.path.join(path, files[0]))
    got = image["channels"]["value"]
    assert got.dtype == np.float32 and got.shape == (H, W)
    np.testing.assert_array_equal(got, value)  # row 0 = the image's top row
    assert image["channels"]["id"].dtype == np.uint32
    np.testing.assert_array_equal(image["channels"]["id"], ids)
    assert image["meta"]["time"] == 0.5
    assert image["meta"]["kind"].tolist() == [b"a"]


def write_raw(path, build):
    with h5py.File(path, "w") as f:
        build(f)


def one_product_db(tmp_path, build):
    folder = tmp_path / "hostile.cdb"
    folder.mkdir()
    write_raw(folder / "x.h5", build)
    (folder / "data.csv").write_text("time,FILE\n1,x.h5\n")
    return dr.Database(str(folder))


HOSTILE = {
    "no channels group": (lambda f: f.create_group("meta"), "no group 'channels'"),
    "a 1-D channel": (lambda f: f.create_dataset("channels/v", data=np.zeros(5)), "1 dimensions"),
    "text in a channel": (lambda f: f.create_dataset("channels/v", data=np.array([[b"ab"]])),
                          "expected integers or floats"),
    "channels of two sizes": (lambda f: (f.create_dataset("channels/a", data=np.zeros((2, 3))),
                                         f.create_dataset("channels/b", data=np.zeros((3, 2)))),
                              "every channel must be one size"),
    "a huge declared size": (lambda f: f.create_dataset("channels/v", shape=(1 << 20, 1 << 20), dtype="f4",
                                                        chunks=(1, 1024)),
                             "exceed"),
    "an external link": (lambda f: f.__setitem__("channels/v", h5py.ExternalLink("/etc/hostname", "/x")),
                         "external link"),
    "external raw storage": (lambda f: f.create_dataset("channels/v", shape=(2, 2), dtype="f4",
                                                        external=[("/dev/zero", 0, 16)]),
                             "external files"),
    "an empty channels group": (lambda f: f.create_group("channels"), "holds no dataset"),
}


@pytest.mark.parametrize("case", sorted(HOSTILE))
def test_a_hostile_h5_is_an_error_naming_the_file_and_what_was_expected(tmp_path, case):
    build, expected = HOSTILE[case]
    db = one_product_db(tmp_path, build)
    with pytest.raises(dr.Error, match=expected) as e:
        db.read(entry=0)
    assert "x.h5" in str(e.value)
