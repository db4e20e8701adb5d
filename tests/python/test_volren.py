"""The `volren` Python module against the `volren` program's images (ctest: Python.VolrenModule).

Run by ctest with PYTHONPATH=build/python and the paths below in the environment; by hand:
  PYTHONPATH=build/python VOLREN_TEST_CLI=build/bin/volren VOLREN_TEST_SOURCE_DIR=. \
      /usr/bin/python3 -m unittest -v tests/python/test_volren.py
The CLI's images are independent expectations: the same data written as NRRD by this file (not
by volren), rendered by the `volren` binary to .exr, read back through OpenImageIO.
"""
import os
import shutil
import subprocess
import tempfile
import unittest

import numpy

import volren

CLI = os.path.abspath(os.environ["VOLREN_TEST_CLI"]) if os.environ.get("VOLREN_TEST_CLI") else ""
SOURCE_DIR = os.environ.get("VOLREN_TEST_SOURCE_DIR", "")
SHARED_DATA = os.environ.get("VOLREN_TEST_SHARED_DATA", "")
REQUIRE_SHARED = os.environ.get("VOLREN_REQUIRE_SHARED_DATA") == "1"

WIDTH, HEIGHT = 64, 48  # not square: the framing's aspect is checked too
SIZE = (WIDTH, HEIGHT)
CLI_SIZE = "%dx%d" % SIZE
SPACING = (1.0, 1.5, 2.0)  # (x, y, z), anisotropic so that a swapped axis shows

NRRD_TYPES = {"uint8": "uint8", "int8": "int8", "uint16": "uint16", "int16": "int16", "float32": "float"}


def write_nrrd(path, array, spacing):
    """Writes a [z, y, x] array as a raw NRRD (x fastest), independently of volren's writer."""
    z, y, x = array.shape
    header = ("NRRD0004\ntype: %s\ndimension: 3\nsizes: %d %d %d\nspacings: %r %r %r\nencoding: raw\n"
              "endian: little\n\n" % (NRRD_TYPES[array.dtype.name], x, y, z, *spacing))
    with open(path, "wb") as out:
        out.write(header.encode("ascii"))
        out.write(numpy.ascontiguousarray(array, dtype=array.dtype.newbyteorder("<")).tobytes())


def write_tf(path, points):
    """Writes control points as an OSG .tf file with components in [0, 1]."""
    with open(path, "w") as out:
        out.write("colour-scale 1\n")
        for p in points:
            out.write("%r %r %r %r %r\n" % tuple(p))


def sample_volume(dtype):
    """A 28 x 24 x 20 (x, y, z) volume, asymmetric along every axis: a ball whose values rise
    with x, and a bright bar at high z and low x."""
    z, y, x = numpy.mgrid[0:20, 0:24, 0:28]
    ball = ((x - 14) ** 2 + (y - 12) ** 2 + (z - 10) ** 2) < 64
    values = ball * (50.0 + 4.0 * x) + ((z > 14) & (x < 8)) * 200.0
    values = numpy.clip(values, 0, 255)
    if dtype == numpy.int16:
        return (values * 10 - 300).astype(numpy.int16)  # negative values too
    if dtype == numpy.float32:
        values = (values / 100.0).astype(numpy.float32)
        values[0, 0, 0] = numpy.nan  # NaN voxels render as empty, on both sides
        return values
    return values.astype(dtype)


class CliTestCase(unittest.TestCase):
    """Runs the `volren` program in a temporary folder."""

    def setUp(self):
        if not CLI or not os.path.exists(CLI):
            self.fail("VOLREN_TEST_CLI (the volren program) is not set or missing: %r" % CLI)
        self.dir = tempfile.mkdtemp(prefix="volren-python-test-")

    def tearDown(self):
        shutil.rmtree(self.dir, ignore_errors=True)

    def path(self, name):
        return os.path.join(self.dir, name)

    def cli(self, *args, expect=0):
        run = subprocess.run([CLI, *args], cwd=self.dir, capture_output=True, text=True, timeout=120)
        self.assertEqual(run.returncode, expect, "volren %s\n%s%s" % (" ".join(args), run.stdout, run.stderr))
        return run

    def cli_render(self, *args):
        """`volren render ARGS -o out.exr --size WxH` read back: float RGBA, top row first."""
        out = self.path("cli.exr")
        self.cli("render", *args, "-o", out, "--size", CLI_SIZE)
        return volren.read_image(out)

    def assertImagesEqual(self, actual, expected, tolerance=1e-6):
        self.assertEqual(actual.shape, expected.shape)
        diff = numpy.abs(actual.astype(numpy.float64) - expected.astype(numpy.float64))
        worst = numpy.unravel_index(numpy.argmax(diff), diff.shape)
        self.assertLessEqual(diff.max(), tolerance, "largest difference %g at (row, column, channel) %s: %g vs %g"
                             % (diff.max(), worst, actual[worst], expected[worst]))

    def assertShowsSomething(self, image):
        self.assertGreater(image[..., 3].max(), 0.2, "the image is (nearly) empty")


class RenderMatchesCli(CliTestCase):
    """render(array) gives the pixels `volren render` gives for the same data in a file."""

    def test_default_view_of_each_voxel_type_equals_cli(self):
        for dtype in (numpy.uint8, numpy.int16, numpy.float32):
            with self.subTest(dtype=numpy.dtype(dtype).name):
                array = sample_volume(dtype)
                write_nrrd(self.path("v.nrrd"), array, SPACING)
                image = volren.render(array, spacing=SPACING, size=SIZE)
                self.assertShowsSomething(image)
                self.assertImagesEqual(image, self.cli_render("v.nrrd"))
        # The same comparison by the CLI's own reader: `volren compare` of the two .exr files.
        volren.save_image(image, self.path("py.exr"))
        compared = self.cli("compare", "py.exr", "cli.exr").stdout
        self.assertRegex(compared, r"max abs error:\s+0 ", compared)

    def test_camera_tf_points_and_background_equal_cli(self):
        array = sample_volume(numpy.uint16)
        write_nrrd(self.path("v.nrrd"), array, SPACING)
        points = [(0, 0, 0, 0, 0), (60, 0.9, 0.4, 0.1, 0.02), (150, 1.0, 0.9, 0.6, 0.3), (255, 1, 1, 1, 0.8)]
        write_tf(self.path("ramp.tf"), points)
        camera = {"eye": (60, -80, 40), "center": (0, 0, 5), "up": (0, 0, 1), "fov": 25}
        expected = self.cli_render("v.nrrd", "--tf", "ramp.tf", "--eye", "60,-80,40", "--center", "0,0,5",
                                   "--up", "0,0,1", "--fov", "25", "--background", "0.1,0.2,0.3")
        from_points = volren.render(array, spacing=SPACING, tf=points, size=SIZE, camera=camera,
                                    background=(0.1, 0.2, 0.3))
        self.assertShowsSomething(from_points)
        self.assertImagesEqual(from_points, expected)
        # The same through the file, and the camera as keyword arguments.
        from_file = volren.render(array, spacing=SPACING, tf=self.path("ramp.tf"), size=SIZE,
                                  background=(0.1, 0.2, 0.3), **camera)
        self.assertImagesEqual(from_file, expected)

    def test_orthographic_fit_equals_cli(self):
        array = sample_volume(numpy.uint8)
        write_nrrd(self.path("v.nrrd"), array, SPACING)
        image = volren.render(array, spacing=SPACING, size=SIZE, ortho="fit", eye=(0, -50, 0), center=(0, 0, 0))
        self.assertShowsSomething(image)
        self.assertImagesEqual(image, self.cli_render("v.nrrd", "--ortho", "fit", "--eye", "0,-50,0",
                                                      "--center", "0,0,0"))

    def test_settings_keywords_change_the_image_as_cli_set_does(self):
        array = sample_volume(numpy.uint8)
        write_nrrd(self.path("v.nrrd"), array, SPACING)
        default = volren.render(array, spacing=SPACING, size=SIZE)
        mip = volren.render(array, spacing=SPACING, size=SIZE, traversal="mip", samplerate=3.5)
        self.assertGreater(numpy.abs(mip - default).max(), 0.05, "traversal='mip' changed nothing")
        self.assertImagesEqual(mip, self.cli_render("v.nrrd", "--set", "traversal=mip", "--set", "samplerate=3.5"))
        unlit = volren.render(array, spacing=SPACING, size=SIZE, lighting=False, earlyTermination=1,
                              forceNull=["Jitter"])
        self.assertGreater(numpy.abs(unlit - default).max(), 0.01, "lighting=False changed nothing")
        self.assertImagesEqual(unlit, self.cli_render("v.nrrd", "--set", "lighting=off", "--set",
                                                      "earlyTermination=1", "--set", "forceNull=Jitter"))

    def test_loaded_volume_renders_as_its_array(self):
        array = sample_volume(numpy.int16)
        write_nrrd(self.path("v.nrrd"), array, SPACING)
        volume = volren.load(self.path("v.nrrd"))
        self.assertImagesEqual(volren.render(volume, size=SIZE), volren.render(array, spacing=SPACING, size=SIZE))
        made = volren.Volume(array, spacing=SPACING)
        self.assertImagesEqual(volren.render(made, size=SIZE), volren.render(volume, size=SIZE))


class RenderSceneMatchesCli(CliTestCase):
    """render_scene(inputs) gives the pixels of `volren render INPUT...`."""

    def test_default_scene_equals_cli(self):
        image = volren.render_scene(None, size=SIZE)
        self.assertShowsSomething(image)
        self.assertImagesEqual(image, self.cli_render())

    def test_shared_dataset_equals_cli(self):
        mhd = os.path.join(SHARED_DATA, "mri", "HeadMRVolume.mhd")
        if not os.path.exists(mhd):
            if REQUIRE_SHARED:
                self.fail("missing shared dataset " + mhd)
            self.skipTest("no shared dataset " + mhd)
        image = volren.render_scene(mhd, size=SIZE, samplerate=1)
        self.assertShowsSomething(image)
        self.assertImagesEqual(image, self.cli_render(mhd, "--set", "samplerate=1"))
        self.assertImagesEqual(volren.render(volren.load(mhd), size=SIZE, samplerate=1), image)

    def test_placed_volume_and_model_equal_cli(self):
        write_nrrd(self.path("ball.nrrd"), sample_volume(numpy.uint8), (1, 1, 1))
        with open(self.path("plate.obj"), "w") as out:
            # OBJ is y-up; OSG's reader turns it z-up: a 40 x 20 plate in the xy plane facing +z.
            out.write("v -20 0 10\nv 20 0 10\nv 20 0 -10\nv -20 0 -10\nvn 0 1 0\nf 1//1 2//1 3//1 4//1\n")
        top = ["--eye", "0,0,100", "--center", "0,0,0", "--up", "0,1,0", "--ortho", "100"]
        image = volren.render_scene([self.path("ball.nrrd"), self.path("plate.obj")], place={2: "0,25,5"},
                                    size=SIZE, eye=(0, 0, 100), center=(0, 0, 0), up=(0, 1, 0), ortho=100)
        expected = self.cli_render("ball.nrrd", "plate.obj", "--place", "2:0,25,5", *top)
        self.assertShowsSomething(image)
        self.assertImagesEqual(image, expected)
        unplaced = volren.render_scene([self.path("ball.nrrd"), self.path("plate.obj")], size=SIZE,
                                       eye=(0, 0, 100), center=(0, 0, 0), up=(0, 1, 0), ortho=100)
        self.assertGreater(numpy.abs(unplaced - image).max(), 0.1, "place moved nothing")


class ImagesAndFiles(CliTestCase):
    """Shape, orientation and the image files."""

    def test_image_shape_dtype_and_orientation(self):
        # A slab at high z and low x, seen from -y with +z up: +z is up (row 0 is the top) and
        # +x is to the right, so the slab fills the top-left of the image only.
        array = numpy.zeros((32, 32, 32), numpy.uint8)
        array[24:, :, :8] = 255
        opaque = [(0, 1, 1, 1, 0), (255, 1, 1, 1, 1)]
        image = volren.render(array, tf=opaque, size=SIZE, eye=(0, -200, 0), center=(0, 0, 0), up=(0, 0, 1),
                              ortho=40, lighting=False)
        self.assertEqual(image.shape, (HEIGHT, WIDTH, 4))
        self.assertEqual(image.dtype, numpy.float32)
        self.assertTrue(image.flags["C_CONTIGUOUS"])
        alpha = image[..., 3]
        # 40 world units over 48 rows: the box spans rows 4..43, columns 12..51; the slab z 24..31
        # rows 4..13, x 0..7 columns 12..21.
        self.assertGreater(alpha[5:12, 13:20].min(), 0.99, "slab not at the top left")
        self.assertLess(alpha[16:, :].max(), 1e-6, "something below the slab")
        self.assertLess(alpha[:, 24:].max(), 1e-6, "something right of the slab")

    def test_all_zero_volume_is_transparent_over_the_background(self):
        background = (0.25, 0.5, 0.75)
        zeros = numpy.zeros((8, 9, 10), numpy.uint8)
        image = volren.render(zeros, tf=[(0, 1, 1, 1, 0), (255, 1, 1, 1, 1)], size=SIZE, background=background)
        self.assertEqual(image[..., 3].max(), 0.0)
        for c in range(3):
            self.assertTrue(numpy.all(image[..., c] == numpy.float32(background[c])))
        # The histogram's TF shows a constant volume as a faint grey box (AutoTransferFunction),
        # in the CLI too.
        write_nrrd(self.path("zeros.nrrd"), zeros, (1, 1, 1))
        faint = volren.render(zeros, size=SIZE, background=background)
        self.assertGreater(faint[..., 3].max(), 0.0)
        self.assertImagesEqual(faint, self.cli_render("zeros.nrrd", "--background", "0.25,0.5,0.75"))

    def test_renderers_are_reused_and_give_the_same_image(self):
        array = sample_volume(numpy.uint8)
        first = volren.render(array, size=SIZE)
        other = volren.render(array, size=(32, 32))
        self.assertEqual(other.shape, (32, 32, 4))
        self.assertImagesEqual(volren.render(array, size=SIZE), first, tolerance=0.0)

    def test_save_image_writes_what_the_cli_writes(self):
        array = sample_volume(numpy.uint8)
        write_nrrd(self.path("v.nrrd"), array, SPACING)
        image = volren.render(array, spacing=SPACING, size=SIZE, background=(0.1, 0.1, 0.1))
        self.cli("render", "v.nrrd", "-o", "cli.png", "--size", CLI_SIZE, "--background", "0.1,0.1,0.1")
        volren.save_image(image, self.path("py.png"))
        png = volren.read_image(self.path("py.png"))
        self.assertEqual(png.shape, (HEIGHT, WIDTH, 3))
        self.assertImagesEqual(png, volren.read_image(self.path("cli.png")), tolerance=0.0)
        rounded = numpy.round(numpy.clip(image[..., :3], 0, 1) * 255) / 255
        self.assertImagesEqual(png, rounded.astype(numpy.float32))
        volren.save_image(image, self.path("py.exr"))
        self.assertImagesEqual(volren.read_image(self.path("py.exr")), image, tolerance=0.0)


class VolumeObjects(CliTestCase):

    def test_load_gives_the_voxels_spacing_and_dims(self):
        array = sample_volume(numpy.uint16)
        write_nrrd(self.path("v.nrrd"), array, SPACING)
        volume = volren.load(self.path("v.nrrd"))
        self.assertEqual(volume.dims, (28, 24, 20))
        self.assertEqual(volume.shape, (20, 24, 28))
        self.assertEqual(volume.spacing, SPACING)
        self.assertEqual(volume.dtype, numpy.uint16)
        self.assertEqual(volume.path, self.path("v.nrrd"))
        self.assertTrue(numpy.array_equal(volume.array, array))
        self.assertFalse(volume.array.flags.writeable)
        self.assertIn("v.nrrd", repr(volume))
        self.assertIn("dims=(28, 24, 20)", repr(volume))
        made = volren.Volume(array[:, :, ::2], spacing=(2, 1.5, 2))  # strided: copied
        self.assertTrue(numpy.array_equal(made.array, array[:, :, ::2]))
        self.assertIsNone(made.path)
        self.assertEqual(made.value_range, (float(array[:, :, ::2].min()), float(array[:, :, ::2].max())))


class Errors(CliTestCase):
    """Errors are Python exceptions with the CLI's messages; nothing crashes."""

    def test_missing_file_is_volren_error_naming_it(self):
        missing = self.path("no-such-volume.nrrd")
        with self.assertRaises(volren.Error) as caught:
            volren.load(missing)
        self.assertIn("no-such-volume.nrrd", str(caught.exception))
        self.assertIsInstance(caught.exception, RuntimeError)
        cwd = os.getcwd()
        os.chdir(self.dir)  # the message lists the folders searched, the current one first
        try:
            with self.assertRaises(volren.Error) as caught:
                volren.render_scene(missing, size=SIZE)
        finally:
            os.chdir(cwd)
        self.assertIn(str(caught.exception), self.cli("render", missing, "-o", "x.exr", expect=1).stderr)
        with self.assertRaises(volren.Error) as caught:
            volren.render(numpy.ones((4, 4, 4), numpy.uint8), tf=self.path("missing.tf"), size=SIZE)
        self.assertIn("missing.tf", str(caught.exception))

    def test_float64_arrays_are_stored_as_float32(self):
        # numpy's default dtype: the same picture as the float32 array, and refused beyond float32's range.
        z, y, x = numpy.mgrid[0:12, 0:12, 0:12]
        ball = numpy.clip(1.0 - numpy.sqrt((x - 5.5) ** 2 + (y - 5.5) ** 2 + (z - 5.5) ** 2) / 6.0, 0.0, 1.0)
        self.assertEqual(ball.dtype, numpy.float64)
        ball[0, 0, 0] = numpy.nan
        wide, narrow = volren.render(ball, size=SIZE), volren.render(ball.astype(numpy.float32), size=SIZE)
        self.assertGreater(float(narrow[..., 3].max()), 0.1)
        numpy.testing.assert_array_equal(wide, narrow)
        self.assertEqual(volren.Volume(ball).dtype, numpy.float32)
        ball[1, 1, 1] = 1e39
        with self.assertRaisesRegex(ValueError, "float32's range"):
            volren.render(ball, size=SIZE)

    def test_bad_arrays(self):
        with self.assertRaisesRegex(TypeError, "float16"):
            volren.render(numpy.zeros((4, 4, 4), numpy.float16), size=SIZE)
        with self.assertRaisesRegex(TypeError, "bool"):
            volren.render(numpy.zeros((4, 4, 4), bool), size=SIZE)
        with self.assertRaisesRegex(ValueError, "3-D"):
            volren.render(numpy.zeros((4, 4), numpy.uint8), size=SIZE)
        with self.assertRaisesRegex(ValueError, "3-D"):
            volren.Volume(numpy.zeros((2, 4, 4, 4), numpy.float32))
        with self.assertRaisesRegex(ValueError, "spacing"):
            volren.render(numpy.zeros((4, 4, 4), numpy.uint8), spacing=(1, 0, 1), size=SIZE)

    def test_unknown_setting_names_the_key_as_the_cli_does(self):
        array = numpy.ones((4, 4, 4), numpy.uint8)
        write_nrrd(self.path("v.nrrd"), array, (1, 1, 1))
        with self.assertRaisesRegex(ValueError, "noSuchSetting") as caught:
            volren.render(array, size=SIZE, noSuchSetting=3)
        stderr = self.cli("render", "v.nrrd", "-o", "x.exr", "--set", "noSuchSetting=3", expect=2).stderr
        self.assertIn(str(caught.exception), stderr)
        with self.assertRaisesRegex(ValueError, "traversal"):
            volren.render(array, size=SIZE, traversal="no_such_traversal")
        with self.assertRaises(TypeError):
            volren.render(array, size=SIZE, samplerate=object())

    def test_bad_arguments(self):
        array = numpy.ones((4, 4, 4), numpy.uint8)
        for kwargs in ({"size": (0, 10)}, {"size": (10,)}, {"samples": 0}, {"background": (2, 0, 0)},
                       {"fov": 10, "ortho": "fit"}, {"fov": 200}, {"ortho": -1}, {"camera": {"eyes": (1, 2, 3)}},
                       {"eye": (1, 2)}, {"eye": (0, 0, 0), "center": (0, 0, 0)}, {"tf": [(0, 2, 0, 0, 0)]},
                       {"tf": [(0, 1, 1)]}):
            with self.subTest(kwargs=kwargs), self.assertRaises((ValueError, TypeError)):
                volren.render(array, **{"size": SIZE, **kwargs})
        with self.assertRaisesRegex(ValueError, "place 3"):
            volren.render_scene(["a.nrrd", "b.obj"], place={3: "0,0,0"})
        with self.assertRaisesRegex(ValueError, "place 1"):
            volren.render_scene(["a.nrrd"], place={1: "0,0"})
        with self.assertRaises(TypeError):
            volren.render_scene(42)


class ModuleDocumentation(unittest.TestCase):

    def test_everything_public_is_documented(self):
        self.assertTrue(volren.__doc__ and "render" in volren.__doc__)
        self.assertRegex(volren.__version__, r"^\d+\.\d+\.\d+$")
        for name in ("render", "render_scene", "load", "save_image", "read_image", "settings_help",
                     "release_renderers", "Volume", "Error"):
            with self.subTest(name=name):
                self.assertGreater(len(getattr(volren, name).__doc__ or ""), 40)
        self.assertIn("traversal", volren.settings_help())
        self.assertIn("TOP row first", volren.render.__doc__)


if __name__ == "__main__":
    unittest.main()
