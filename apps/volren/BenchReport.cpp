#include "BenchReport.h"
#include "BenchFront.h"
#include "SceneSetup.h"

#include <volume_renderer/SampleDistance.h>

#include <volume_model/DefaultScene.h>
#include <volume_model/ReadVolume.h>
#include <volume_model/TransferFunction.h>
#include <volume_model/VolumeNode.h>

#include <nlohmann/json.hpp>
#include <osgDB/FileNameUtils>
#include <osgDB/FileUtils>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>
#include <stdexcept>

namespace volren::app {

ImageError imageError(const osg::Image& image, const ReferenceImage& truth)
{
    if (image.s() != truth.width || image.t() != truth.height)
        throw std::runtime_error("bench: image and reference differ in size");
    const auto* rgba = reinterpret_cast<const float*>(image.data());
    ImageError e;
    double sum = 0.0, worst = 0.0;
    for (std::size_t i = 0; i < truth.rgba.size(); ++i) {
        const double d = double(rgba[i]) - truth.rgba[i];
        sum += d * d;
        worst = std::max(worst, std::abs(d));
    }
    e.rmse = std::sqrt(sum / double(truth.rgba.size()));
    e.maxAbs = worst;
    e.psnr = e.rmse > 0.0 ? 20.0 * std::log10(1.0 / e.rmse) : 999.0;
    return e;
}

namespace {

std::string number(double v, int digits = 3)
{
    if (v < 0.0) return "";
    std::ostringstream out;
    out << std::setprecision(digits) << v;
    return out.str();
}

void writeMarkdown(const BenchReport& report, const std::string& path)
{
    std::ofstream md(path);
    md << "GL context: " << report.context << "  \n" << report.timingNote << ".\n\n";
    md << "| dataset | size | renderer | configuration | frame ms | GPU ms | CPU ms | textures MB | GPU memory MB | RMSE | "
          "max error | PSNR dB | Pareto | beats default | light moving ms | rebuild ms | aux B/voxel |\n";
    md << "|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|:-:|:-:|---:|---:|---:|\n";
    for (const BenchRow& r : report.rows)
        md << "| " << r.dataset << " | " << r.width << "x" << r.height << " | " << r.renderer
           << " | " << r.config << " | " << number(r.frameMs) << " | " << number(r.gpuMs) << " | " << number(r.cpuMs)
           << " | " << number(r.textureMb) << " | " << number(r.gpuMemoryMb) << " | " << number(r.error.rmse) << " | "
           << number(r.error.maxAbs) << " | " << number(r.error.psnr) << " | " << (r.pareto ? "yes" : "") << " | "
           << (r.beatsDefault ? "yes" : "") << " | " << number(r.lightMoveMs) << " | " << number(r.rebuildMs) << " | "
           << number(r.auxBytesPerVoxel) << " |\n";
}

void writeCsv(const BenchReport& report, const std::string& path)
{
    std::ofstream csv(path);
    csv << "dataset,width,height,renderer,config,truth,frame_ms,gpu_ms,cpu_ms,texture_mb,gpu_memory_mb,rmse,max_abs,"
           "psnr_db,pareto,beats_default,light_move_ms,rebuild_ms,aux_bytes_per_voxel\n";
    auto quoted = [](const std::string& s) { return "\"" + s + "\""; };
    for (const BenchRow& r : report.rows)
        csv << quoted(r.dataset) << "," << r.width << "," << r.height << "," << quoted(r.renderer) << ","
            << quoted(r.config) << "," << quoted(r.truth) << "," << r.frameMs << "," << r.gpuMs << "," << r.cpuMs << ","
            << r.textureMb << "," << r.gpuMemoryMb << "," << r.error.rmse << "," << r.error.maxAbs << "," << r.error.psnr
            << "," << (r.pareto ? 1 : 0) << "," << (r.beatsDefault ? 1 : 0) << "," << r.lightMoveMs << "," << r.rebuildMs
            << "," << r.auxBytesPerVoxel << "\n";
}

void writeJson(const BenchReport& report, const std::string& path)
{
    nlohmann::json rows = nlohmann::json::array();
    for (const BenchRow& r : report.rows)
        rows.push_back({{"dataset", r.dataset}, {"width", r.width}, {"height", r.height}, {"renderer", r.renderer},
                        {"config", r.config}, {"truth", r.truth}, {"frame_ms", r.frameMs}, {"gpu_ms", r.gpuMs},
                        {"cpu_ms", r.cpuMs}, {"texture_mb", r.textureMb}, {"gpu_memory_mb", r.gpuMemoryMb},
                        {"rmse", r.error.rmse}, {"max_abs", r.error.maxAbs}, {"psnr_db", r.error.psnr},
                        {"pareto", r.pareto}, {"beats_default", r.beatsDefault},
                        {"beaten_by_default", r.beatenByDefault}, {"composition_keys", r.keys},
                        {"light_move_ms", r.lightMoveMs}, {"rebuild_ms", r.rebuildMs},
                        {"aux_bytes_per_voxel", r.auxBytesPerVoxel}});
    nlohmann::json doc = {{"context", report.context}, {"timing_note", report.timingNote}, {"rows", rows}};
    std::ofstream(path) << doc.dump(2) << "\n";
}

/// The plot of the first dataset and size: every configuration, the front as a line, the peer.
void writePlot(const BenchReport& report, const std::string& directory)
{
    if (report.rows.empty()) return;
    const BenchRow& first = report.rows.front();
    std::ofstream points(directory + "/bench-points.dat"), front(directory + "/bench-front.dat"),
        peer(directory + "/bench-peer.dat");
    std::vector<const BenchRow*> onFront;
    for (const BenchRow& r : report.rows) {
        if (r.dataset != first.dataset || r.width != first.width || r.height != first.height || !(r.error.rmse > 0.0))
            continue;
        std::ofstream& out = r.renderer == "volren" ? points : peer;
        out << r.frameMs << " " << r.error.rmse << " \"" << r.config << "\"\n";
        if (r.pareto && r.truth == first.truth) onFront.push_back(&r);
    }
    std::sort(onFront.begin(), onFront.end(), [](const BenchRow* a, const BenchRow* b) { return a->frameMs < b->frameMs; });
    for (const BenchRow* r : onFront) front << r->frameMs << " " << r->error.rmse << "\n";
    points.close();
    front.close();
    peer.close();

    std::ofstream gp(directory + "/bench.gp");
    gp << "set terminal pngcairo size 1000,640 font 'DejaVu Sans,10'\n"
       << "set output '" << directory << "/bench.png'\n"
       << "set title 'volren bench: " << first.dataset << ", " << first.width << "x" << first.height << ", "
       << report.context.substr(report.context.rfind(" / ") == std::string::npos ? 0 : report.context.rfind(" / ") + 3)
       << "' noenhanced\n"
       << "set logscale xy\nset grid\nset key top right\n"
       << "set xlabel 'frame time, ms (median draw time)'\nset ylabel 'RMSE against the CPU reference'\n"
       << "set label 'front over the configurations drawing the default lighting' at graph 0.02,0.04 font ',8'\n"
       << "plot '" << directory << "/bench-front.dat' using 1:2 with lines lw 2 lc rgb '#d62728' title 'Pareto front', \\\n"
       << "     '" << directory << "/bench-points.dat' using 1:2 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'volren "
          "configurations', \\\n"
       << "     '" << directory << "/bench-points.dat' using 1:2:3 with labels offset char 0.6,0.6 left font ',8' "
          "noenhanced notitle";
    std::ifstream check(directory + "/bench-peer.dat");
    if (check.peek() != std::ifstream::traits_type::eof())
        gp << ", \\\n     '" << directory << "/bench-peer.dat' using 1:2 with points pt 5 ps 1.6 lc rgb '#2ca02c' "
           << "title 'VTK GPU ray caster', \\\n     '" << directory
           << "/bench-peer.dat' using 1:2:3 with labels offset char 0.6,-0.8 left font ',8' noenhanced notitle";
    gp << "\n";
    gp.close();
    if (std::system(("gnuplot '" + directory + "/bench.gp' 2>'" + directory + "/gnuplot.log'").c_str()) != 0)
        std::cerr << "volren bench: no plot (gnuplot missing or failed, see " << directory
                  << "/gnuplot.log); the script is " << directory << "/bench.gp" << std::endl;
}

}  // namespace

void writeReport(BenchReport& report, const std::string& directory)
{
    if (!osgDB::makeDirectory(directory)) throw std::runtime_error(directory + ": cannot create the folder");
    markPareto(report.rows);
    markRowsBeatingTheDefault(report.rows);
    writeMarkdown(report, directory + "/bench.md");
    writeCsv(report, directory + "/bench.csv");
    writeJson(report, directory + "/bench.json");
    writePlot(report, directory);
}

std::pair<BenchRow, osg::ref_ptr<osg::Image>> runVtkPeer(const VolumeScene& scene, const ReferenceCamera& camera,
                                                         int frames, const std::string& directory)
{
    const std::vector<VolumeNode*> nodes = findVolumeNodes(const_cast<VolumeScene&>(scene));
    if (nodes.size() != 1) throw std::runtime_error("bench --vtk: the scene must hold exactly one volume");
    const VolumeNode& node = *nodes.front();
    const Volume& volume = *node.getVolume();
    if (volume.sourceFile.empty()) throw std::runtime_error("bench --vtk: the volume has no file VTK could read");

    // What VTK is told: the file, the TF, the camera (eye, centre, up, vertical field of view),
    // the size, the step (world units; TF opacity per smallest spacing) and the lighting.
    osg::Vec3d eye, centre, up;
    camera.view.getLookAt(eye, centre, up);
    double fovy = 0, aspect = 0, zNear = 0, zFar = 0;
    if (!camera.projection.getPerspective(fovy, aspect, zNear, zFar))
        throw std::runtime_error("bench --vtk: only perspective views are passed to VTK");
    nlohmann::json points = nlohmann::json::array();
    for (const auto& [value, rgba] : node.getTransferFunction()->points())
        points.push_back({value, rgba.r(), rgba.g(), rgba.b(), rgba.a()});
    const double step = effectiveSampleDistance(node);  // the step volren marches
    const nlohmann::json spec = {
        {"volume", volume.sourceFile},
        {"spacing", {volume.spacing().x(), volume.spacing().y(), volume.spacing().z()}},
        {"domain", {node.getTransferFunction()->domainMin(), node.getTransferFunction()->domainMax()}},
        {"points", points},
        {"eye", {eye.x(), eye.y(), eye.z()}},
        {"center", {centre.x(), centre.y(), centre.z()}},
        {"up", {up.x(), up.y(), up.z()}},
        {"fovy", fovy},
        {"near", zNear},
        {"far", zFar},
        {"width", camera.width},
        {"height", camera.height},
        {"sample_distance", step},
        {"unit_distance", volume.minSpacing()},
        {"lighting", scene.pass.lighting},
        {"ambient", node.settings.number("ambient")},
        {"specular", node.settings.number("specular")},
        {"shininess", node.settings.number("shininess")},
        {"frames", frames},
        {"output", directory + "/vtk.f32"},
        {"timing", directory + "/vtk.json"}};
    osgDB::makeDirectory(directory);
    std::ofstream(directory + "/vtk-spec.json") << spec.dump(2) << "\n";
    const std::string script = osgDB::concatPaths(shareDirectory(), "tools/bench_vtk.py");
    const std::string command = "xvfb-run -a -s '-screen 0 1024x768x24' /usr/bin/python3 '" + script + "' '" + directory +
                                "/vtk-spec.json' > '" + directory + "/vtk.log' 2>&1";
    if (std::system(command.c_str()) != 0)
        throw std::runtime_error("bench --vtk: the VTK peer failed (python3-vtk9 and xvfb installed? see " + directory +
                                 "/vtk.log)");
    nlohmann::json timing;
    std::ifstream(directory + "/vtk.json") >> timing;
    BenchRow row;
    row.renderer = "VTK " + timing.value("version", std::string("?"));
    row.config = "vtkGPUVolumeRayCastMapper, same step";
    row.width = camera.width;
    row.height = camera.height;
    row.frameMs = timing.value("frame_ms", -1.0);
    row.cpuMs = row.frameMs;
    osg::ref_ptr<osg::Image> image = new osg::Image;
    image->allocateImage(camera.width, camera.height, 1, GL_RGBA, GL_FLOAT);
    std::ifstream raw(directory + "/vtk.f32", std::ios::binary);
    raw.read(reinterpret_cast<char*>(image->data()), std::streamsize(image->getTotalSizeInBytes()));
    if (!raw) throw std::runtime_error("bench --vtk: " + directory + "/vtk.f32 is short");
    return {row, image};
}

}  // namespace volren::app
