# Images: channels as read-only numpy views of the planes (no copy, the view
# keeps the plane alive), images from arrays, the picture a notebook shows.
import gc

import numpy as np
import pytest

import darkroom as dr


def test_a_channel_is_a_read_only_view_of_the_plane_without_copy():
    z = np.arange(12, dtype=np.float32).reshape(3, 4)
    img = dr.Image.from_arrays({"Z": z, "id": np.arange(12, dtype=np.uint32).reshape(3, 4)})
    view = img["Z"]
    assert view.shape == (3, 4) and view.dtype == np.float32 and not view.flags.writeable
    np.testing.assert_array_equal(view, z)
    # The same memory every time: a view of the plane, not a copy of it.
    assert img["Z"].__array_interface__["data"][0] == view.__array_interface__["data"][0]
    assert img["id"].dtype == np.uint32
    with pytest.raises(ValueError):
        view[0, 0] = 1
    # The view keeps the plane alive after the image is gone.
    del img
    gc.collect()
    np.testing.assert_array_equal(view, z)


def test_images_from_arrays_say_what_is_wrong():
    with pytest.raises(ValueError, match="first was 2 x 2"):
        dr.Image.from_arrays({"a": np.zeros((2, 2)), "b": np.zeros((3, 2))})
    with pytest.raises(TypeError, match="2-D array"):
        dr.Image.from_arrays({"a": np.zeros(4)})
    with pytest.raises(KeyError, match="the image has a"):
        dr.Image.from_arrays({"a": np.zeros((2, 2))})["b"]


def test_the_picture_is_srgb_colour_or_grey_and_png():
    r = np.full((2, 3), 0.5, np.float32)
    img = dr.Image.from_arrays({"R": r, "G": r * 0, "B": r * 2})
    rgba = img.to_rgba8()
    assert rgba.shape == (2, 3, 4) and rgba.dtype == np.uint8
    assert tuple(rgba[0, 0]) == (188, 0, 255, 255)  # sRGB of linear 0.5 is 0.7354 -> 188
    grey = dr.Image.from_arrays({"Z": np.array([[1.0, 3.0], [np.inf, 2.0]], np.float32)}).to_rgba8()
    assert tuple(grey[0, 0]) == (0, 0, 0, 255) and tuple(grey[0, 1]) == (255, 255, 255, 255)
    assert grey[1, 0, 3] == 0  # no finite value: transparent
    assert img._repr_png_()[:8] == b"\x89PNG\r\n\x1a\n"


def test_the_camera_is_a_python_object():
    cam = dr.Camera()
    cam.position = [0, -5, 0]
    cam.forward = [0, 1, 0]
    cam.width, cam.height = 4, 3
    img = dr.Image.from_arrays({"Z": np.ones((3, 4), np.float32)}, camera=cam, metadata={"units.Z": "m"})
    assert img.camera == cam and img.camera.position == [0, -5, 0]
    assert img.metadata == {"units.Z": "m"}
    assert dr.Image.from_arrays({"Z": np.ones((1, 1))}).camera is None
