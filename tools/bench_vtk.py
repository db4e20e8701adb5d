#!/usr/bin/python3
"""The peer of `volren bench --vtk`: VTK's GPU ray caster (Debian's python3-vtk9, run under
xvfb-run by volren) on the same volume, transfer function, view, image size and sample
distance. Reads the JSON spec volren writes, renders `frames` frames after two warm-up frames,
and writes the last image as raw float32 RGBA (row 0 at the bottom, like volren's read-back)
and the median frame time as JSON.

Conventions matched: the volume is centred at the origin with voxel centres at
(i + 0.5) * spacing - size / 2; TF opacity is per the smallest voxel spacing (scalar opacity
unit distance); no jittering, fixed sample distance; one headlight when the scene is lit."""
import array
import json
import statistics
import sys
import time

import vtk


def reader_for(path):
    lower = path.lower()
    if lower.endswith(".nii") or lower.endswith(".nii.gz"):
        reader = vtk.vtkNIFTIImageReader()
    elif lower.endswith(".nrrd") or lower.endswith(".nhdr"):
        reader = vtk.vtkNrrdReader()
    elif lower.endswith(".mha") or lower.endswith(".mhd"):
        reader = vtk.vtkMetaImageReader()
    else:
        raise SystemExit(f"bench_vtk: no VTK reader for {path}")
    reader.SetFileName(path)
    reader.Update()
    return reader


def main():
    spec = json.load(open(sys.argv[1]))
    reader = reader_for(spec["volume"])
    image = reader.GetOutput()
    dims = image.GetDimensions()
    spacing = spec["spacing"]
    change = vtk.vtkImageChangeInformation()  # volren's placement: centred, its spacing
    change.SetInputConnection(reader.GetOutputPort())
    change.SetOutputSpacing(*spacing)
    change.SetOutputOrigin(*[-(dims[a] - 1) * spacing[a] / 2.0 for a in range(3)])

    colour = vtk.vtkColorTransferFunction()
    opacity = vtk.vtkPiecewiseFunction()
    for value, r, g, b, a in spec["points"]:
        colour.AddRGBPoint(value, r, g, b)
        opacity.AddPoint(value, a)
    prop = vtk.vtkVolumeProperty()
    prop.SetColor(colour)
    prop.SetScalarOpacity(opacity)
    prop.SetScalarOpacityUnitDistance(spec["unit_distance"])
    prop.SetInterpolationTypeToLinear()
    if spec["lighting"]:
        prop.ShadeOn()
        prop.SetAmbient(spec["ambient"])
        prop.SetDiffuse(1.0)
        prop.SetSpecular(spec["specular"])
        prop.SetSpecularPower(spec["shininess"])
    else:
        prop.ShadeOff()

    mapper = vtk.vtkGPUVolumeRayCastMapper()
    mapper.SetInputConnection(change.GetOutputPort())
    mapper.SetAutoAdjustSampleDistances(0)
    mapper.SetSampleDistance(spec["sample_distance"])
    mapper.SetUseJittering(0)
    mapper.SetBlendModeToComposite()
    volume = vtk.vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)

    renderer = vtk.vtkRenderer()
    renderer.AddVolume(volume)
    renderer.SetBackground(0, 0, 0)
    renderer.SetBackgroundAlpha(0.0)
    renderer.SetAutomaticLightCreation(1 if spec["lighting"] else 0)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(*spec["eye"])
    camera.SetFocalPoint(*spec["center"])
    camera.SetViewUp(*spec["up"])
    camera.SetViewAngle(spec["fovy"])
    camera.SetClippingRange(spec["near"], spec["far"])

    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetAlphaBitPlanes(1)
    window.SetMultiSamples(0)
    window.AddRenderer(renderer)
    w, h = spec["width"], spec["height"]
    window.SetSize(w, h)

    times = []
    for frame in range(spec["frames"] + 2):
        start = time.perf_counter()
        window.Render()
        window.WaitForCompletion()
        if frame >= 2:
            times.append((time.perf_counter() - start) * 1000.0)

    pixels = vtk.vtkFloatArray()
    window.GetRGBAPixelData(0, 0, w - 1, h - 1, 0, pixels)
    values = array.array("f", (pixels.GetValue(i) for i in range(w * h * 4)))
    if sys.byteorder != "little":
        values.byteswap()
    with open(spec["output"], "wb") as out:
        values.tofile(out)
    json.dump({"version": vtk.vtkVersion.GetVTKVersion(), "frame_ms": statistics.median(times)},
              open(spec["timing"], "w"))

if __name__ == "__main__":
    main()
