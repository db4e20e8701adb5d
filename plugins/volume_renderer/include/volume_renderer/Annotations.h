#pragma once
#include <volume_renderer/ScaleBar.h>

#include <osg/Camera>
#include <osg/Group>

#include <memory>
#include <mutex>
#include <string>

namespace volren {

/// Screen annotations over a rendered view, added as a child of the scene's root (a
/// VolumeScene): a scale bar in the volumes' length unit in the bottom right corner (the
/// longest round length up to a fifth of the viewport's width, measured at the centre of the
/// scene's bound, labelled "20 µm") and an axis gizmo in the bottom left corner (the world's x,
/// y and z axes as the camera sees them, red, green and blue, labelled). Drawn after the volumes
/// (render bin 1000, no depth test), never part of the scene's bound, its opaque geometry or
/// its reference; both parts off until set. Labels are images of a font's glyphs (DejaVu Sans
/// where installed, else OSG's built-in font) composed on the CPU, drawn by volren's own
/// programs (shaders/Overlay), so they look the same in compatibility, core and headless contexts.
class Annotations : public osg::Group
{
public:
    Annotations();

    /// Shows the scale bar.
    void setScaleBar(bool on);
    bool scaleBar() const { return _scaleBar; }  ///< whether the scale bar is shown
    /// Shows the axis gizmo.
    void setAxes(bool on);
    bool axes() const { return _axes; }  ///< whether the axis gizmo is shown
    /// The unit of world lengths ("µm", "mm"; lengthUnitSymbol()); "" writes bare numbers.
    void setUnit(const std::string& unit) { _unit = unit; }
    const std::string& unit() const { return _unit; }  ///< the scale bar's unit
    /// Colour of the scale bar and the labels (white by default; dark for a light background).
    void setColour(const osg::Vec4& colour);
    /// Pixels on the viewport's left that panels cover (volren view's panel column): the axis
    /// gizmo stands right of them.
    void setLeftMargin(double pixels) { _leftMargin = pixels; }

    /// The scale bar of the last culled frame (no bar before the first) and its label.
    ScaleBar shownScaleBar() const;
    std::string shownLabel() const;  ///< see shownScaleBar

    /// Culls: sizes the bar and turns the gizmo for the camera, then draws both. The shapes are
    /// rewritten for the camera culled last: one view, and a viewer that culls and draws in one
    /// thread (as volren's are).
    void traverse(osg::NodeVisitor& nv) override;
    /// Invalid: annotations take no room in the scene.
    osg::BoundingSphere computeBound() const override { return osg::BoundingSphere(); }

    /// Gizmo geometry (pixels): the origin's offset from the corner and each axis' length.
    static constexpr double gizmoOffset = 52.0, gizmoLength = 36.0;
    /// Scale bar geometry (pixels): margin from the corner, thickness.
    static constexpr double barMargin = 20.0, barThickness = 4.0;

protected:
    ~Annotations() override = default;

private:
    struct Parts;
    void update(const osg::Matrixd& view, const osg::Matrixd& projection, const osg::Viewport& viewport,
                const osg::Vec3d& centre);

    bool _scaleBar = false, _axes = false;
    double _leftMargin = 0.0;
    std::string _unit;
    osg::ref_ptr<osg::Camera> _hud;
    std::shared_ptr<Parts> _parts;
    mutable std::mutex _mutex;
    ScaleBar _shown;
    std::string _label;
};

}  // namespace volren
