// The `volren` Python module: headless volume rendering with the same scenes, settings and images
// as the `volren render` command (python/README.md).
#include "Camera.h"
#include "Conversions.h"
#include "Errors.h"
#include "ImageFiles.h"
#include "PyVolume.h"
#include "RenderOptions.h"
#include "Rendering.h"
#include "Scenes.h"
#include "Settings.h"
#include "TransferFunctionArgument.h"

#include <volume_model/ReadVolume.h>
#include <volume_renderer/CompositionPolicy.h>
#include <volume_renderer/SceneSettings.h>

#include <osgDB/Options>

#include <string>

namespace py = pybind11;
using namespace volren::python;

namespace {

const std::string imageDoc =
    "Returns a float32 numpy array of shape (height, width, 4), TOP row first (numpy's image\n"
    "convention: image[0] is the top row), RGBA premultiplied over the background: alpha is the\n"
    "coverage and RGB already includes background * (1 - alpha), exactly as `volren render -o X.exr`\n"
    "writes it (volren.save_image(image, 'x.png') writes the CLI's 8-bit PNG).\n";

const std::string settingsDoc =
    "**settings: every `volren render --set KEY=VALUE` as a keyword: traversal='mip',\n"
    "samplerate=4, lighting=False, earlyTermination=1, forceNull=['Jitter'] (bool -> on/off,\n"
    "numbers as their shortest exact decimal, lists joined by commas); applied in order, to the\n"
    "pass or to every volume (volren.settings_help() lists them). A bad key or value raises\n"
    "ValueError with the C++ message naming the key.\n";

const std::string tfDoc =
    "tf: None keeps the scene's transfer functions (a volume's default one is made from its\n"
    "    histogram); a path reads a transfer-function file as `--tf` does (.tf, ParaView\n"
    "    presets.json[#Name] stretched over each volume's value range unless tf_keep_range, 3D\n"
    "    Slicer .vp, ImageJ .lut); a list of (value, r, g, b, a) points (value in data units,\n"
    "    components in [0, 1], linear between points) gives every volume that function.\n"
    "tf_keep_range: a ParaView preset keeps its own values (--tf-keep-range).\n";

const std::string commonDoc =
    "size: (width, height) in pixels, 1..16384 each (--size WxH).\n"
    "camera: see below; its keys may also be given as keyword arguments (eye=..., ortho=...).\n"
    "background: (r, g, b), each in [0, 1] (--background).\n"
    "samples: samples per pixel of a multisampled framebuffer, 1..64 (--samples).\n";

py::array_t<float> render(const py::object& volume, const py::object& spacing, const py::object& tf, const py::object& size,
                          const py::object& camera, const py::object& background, const py::object& samples,
                          bool tfKeepRange, py::kwargs settings)
{
    const RenderOptions options = renderOptions(size, camera, background, samples, settings);
    osg::ref_ptr<volren::Volume> shown;
    if (py::isinstance<PyVolume>(volume)) {
        if (!spacing.is_none())
            throw py::value_error("spacing: a volren.Volume has its own spacing (set volume.spacing instead)");
        shown = volume.cast<PyVolume&>().volume;
    } else {
        shown = volumeFromArray(volume, spacing.is_none() ? osg::Vec3d(1.0, 1.0, 1.0) : vec3From(spacing, "spacing"));
    }
    osg::ref_ptr<volren::VolumeScene> scene = volumeScene(*shown);
    applyTransferFunction(*scene, tf, tfKeepRange);
    applySettings(*scene, settings);
    return renderScene(*scene, options);
}

py::array_t<float> renderSceneFiles(const py::object& inputs, const py::object& size, const py::object& camera,
                                    const py::object& tf, bool tfKeepRange, const py::object& place,
                                    const py::object& background, const py::object& samples,
                                    const py::object& readerOptions, py::kwargs settings)
{
    const RenderOptions options = renderOptions(size, camera, background, samples, settings);
    osg::ref_ptr<volren::VolumeScene> scene = inputsScene(inputs, place, readerOptionsText(readerOptions));
    applyTransferFunction(*scene, tf, tfKeepRange);
    applySettings(*scene, settings);
    return renderScene(*scene, options);
}

PyVolume load(const py::object& path, py::kwargs readerOptions)
{
    const std::string file = pathFrom(path, "path");
    const osg::ref_ptr<osgDB::Options> options = new osgDB::Options(readerOptionsText(readerOptions));
    return PyVolume{volren::readVolumeFile(file, options.get())};
}

}  // namespace

PYBIND11_MODULE(volren, m)
{
    m.doc() = R"doc(Headless GPU volume rendering (volren) from Python.

Renders numpy volumes, volume files and scene files without a display (EGL), with the same
scenes, settings and images as the `volren render` command: for the same arguments the pixels
are the same as the CLI's .exr output.

    import numpy, volren
    z, y, x = numpy.mgrid[-1:1:64j, -1:1:64j, -1:1:64j]
    ball = (255 * (x*x + y*y + z*z < 0.8)).astype(numpy.uint8)   # indexed [z, y, x]
    image = volren.render(ball, spacing=(1, 1, 2), size=(256, 256), traversal='mip')
    volren.save_image(image, 'ball.png')                         # like volren render -o ball.png
    head = volren.render_scene(None, size=(128, 128))            # the default scene
    volren.render_scene(['ct.nii.gz', 'tool.obj'], place={2: '0,0,40'}, ortho='fit')

Conventions:
- Arrays are indexed [z, y, x] (C order, x fastest); dims and spacing are (x, y, z).
- Images are float32 (height, width, 4), top row first, premultiplied RGBA over the background.
- C++ failures (unreadable files, shader errors) raise volren.Error (a RuntimeError) with the
  C++ message; bad arguments raise ValueError or TypeError.
- One EGL renderer per (width, height, samples) is kept for the process and reused.
)doc";
    registerErrors(m);
    m.attr("__version__") = VOLREN_VERSION;
    defineVolume(m);

    m.def("render", &render, py::arg("volume"), py::arg("spacing") = py::none(), py::arg("tf") = py::none(),
          py::arg("size") = py::make_tuple(512, 512), py::arg("camera") = py::none(),
          py::arg("background") = py::make_tuple(0.0, 0.0, 0.0), py::arg("samples") = 1, py::arg("tf_keep_range") = false,
          ("Renders one volume as `volren render VOLUMEFILE` renders a file: the volume centred at the\n"
           "origin, a transfer function from its histogram (unless tf), one headlight.\n\n"
           "volume: a numpy array indexed [z, y, x] (3-D; uint8, int8, uint16, int16, float32, or float64\n"
           "    stored as float32 (ValueError beyond its range), else TypeError; NaN voxels render as empty;\n"
           "    any strides), or a volren.Volume (from load()).\n"
           "spacing: voxel size along (x, y, z) for an array (default (1, 1, 1)); a Volume has its own.\n" +
           tfDoc + commonDoc + settingsDoc + "\n" + imageDoc + "\n" + cameraDoc)
              .c_str());

    m.def("render_scene", &renderSceneFiles, py::arg("inputs") = py::none(), py::arg("size") = py::make_tuple(512, 512),
          py::arg("camera") = py::none(), py::arg("tf") = py::none(), py::arg("tf_keep_range") = false,
          py::arg("place") = py::none(), py::arg("background") = py::make_tuple(0.0, 0.0, 0.0), py::arg("samples") = 1,
          py::arg("reader_options") = py::none(),
          ("Renders files as `volren render INPUT...` does.\n\n"
           "inputs: None for the default scene (scenes/default.osgt), or a path or list of paths of scene\n"
           "    (.osgt, .osgb), volume and model (.obj, .ply, ...) files, combined into one scene; names\n"
           "    not found as given are looked up along OSG's data path, as the CLI does.\n"
           "place: {input number: 'tx,ty,tz[:s][:axis,angle]'} moves inputs, numbered from 1 like the\n"
           "    CLI's --place N:SPEC (scale, then rotate by degrees about x|y|z or ax,ay,az, then translate).\n"
           "reader_options: the volume readers' options, a str as -O takes them ('lazy ramBudgetMB=64')\n"
           "    or a dict ({'lazy': True, 'ramBudgetMB': 64}).\n" +
           tfDoc + commonDoc + settingsDoc + "\n" + imageDoc + "\n" + cameraDoc)
              .c_str());

    m.def("load", &load, py::arg("path"),
          "Reads a volume file through volren's readers (NIfTI, NRRD, MetaImage, raw, TIFF stacks,\n"
          "DICOM series, PVM, OME-Zarr, ...; `volren info` reads the same). Keyword arguments are the\n"
          "readers' options, as the CLI's -O: load('big.raw', lazy=True, ramBudgetMB=512,\n"
          "dims='512,512,256', type='uint16') (True is a bare flag, False or None leaves one out).\n"
          "Raises volren.Error naming the file and the reason.");

    m.def("save_image", [](const py::object& image, const py::object& path) { saveImage(image, pathFrom(path, "path")); },
          py::arg("image"), py::arg("path"),
          "Writes an image array (height, width, 3 or 4; top row first, as render returns it) by the\n"
          "rules of `volren render -o`: .exr keeps the float channels (RGBA), every other extension\n"
          "(.png, .jpg, .tif, ...) gets 8-bit RGB, clamped to [0, 1] and rounded (alpha dropped: the\n"
          "colour is already over the background). Raises volren.Error when it cannot be written.");

    m.def("read_image", [](const py::object& path) { return readImage(pathFrom(path, "path")); }, py::arg("path"),
          "Reads an image file (the CLI's .exr, or anything OpenImageIO reads) as float32 (height, width,\n"
          "channels), top row first; 8-bit files are scaled to [0, 1]. Raises volren.Error.");

    m.def("settings_help", [] { return volren::settingsHelp(volren::CompositionPolicy()); },
          "The text of `volren render --help-settings`: every setting keyword with its default and\n"
          "every implementation of every slot.");

    m.def("release_renderers", &releaseRenderers,
          "Frees the process's renderers (their EGL contexts and GPU memory); the next render makes a\n"
          "new one. Called at interpreter exit.");

    // Renderers hold EGL contexts: release them while the interpreter and the libraries still exist.
    py::module_::import("atexit").attr("register")(py::cpp_function(&releaseRenderers));
}
