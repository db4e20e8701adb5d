// Screen annotations: a HUD camera under the scene root whose shapes are resized at cull time
// for the camera being culled (its view, projection and viewport).
#include <volume_renderer/Annotations.h>
#include <volume_renderer/MatrixUniforms.h>
#include <volume_renderer/ShaderFunctionRegistry.h>

#include <volume_model/LengthUnit.h>

#include <osg/BlendFunc>
#include <osg/Depth>
#include <osg/Geode>
#include <osg/Geometry>
#include <osg/Texture2D>
#include <osgText/Font>
#include <osgText/Glyph>
#include <osgText/String>
#include <osgUtil/CullVisitor>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>

namespace volren {

namespace {

/// A text label: a quad over an image of its glyphs (a font's glyph bitmaps composed on the CPU,
/// so that it draws the same in any context, headless ones too).
struct Label
{
    osg::ref_ptr<osg::Geometry> quad;
    osg::ref_ptr<osg::Texture2D> texture = new osg::Texture2D;
    osg::ref_ptr<osg::Uniform> origin = new osg::Uniform("volren_labelOrigin", osg::Vec2(0, 0));
    osg::ref_ptr<osg::Uniform> size = new osg::Uniform("volren_labelSize", osg::Vec2(1, 1));
    std::string text;  ///< what the image shows
};

}  // namespace

/// The shapes the HUD camera draws; resized every cull.
struct Annotations::Parts
{
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    osg::ref_ptr<osg::Geometry> bar;
    Label label;
    std::array<osg::ref_ptr<osg::Geometry>, 3> axes;
    std::array<Label, 3> axisNames;
    osg::ref_ptr<osg::Uniform> colour = new osg::Uniform("volren_annotationColour", osg::Vec4(1, 1, 1, 1));
};

namespace {

/// Label height in pixels (the font's glyphs at this resolution).
constexpr int labelPixels = 14;

/// The labels' font: DejaVu Sans (Debian's fonts-dejavu-core) where it is installed, else OSG's
/// built-in font (ASCII only: a µ becomes u).
osgText::Font* labelFont()
{
    static osg::ref_ptr<osgText::Font> font = [] {
        for (const char* path : {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", "/usr/share/fonts/TTF/DejaVuSans.ttf"})
            if (std::filesystem::exists(path))
                if (osg::ref_ptr<osgText::Font> f = osgText::readRefFontFile(path)) return f;
        return osg::ref_ptr<osgText::Font>(osgText::Font::getDefaultFont());
    }();
    return font.get();
}

/// `utf8` as one image of its glyphs' coverage (GL_RED, row 0 at the bottom), `labelPixels` high.
osg::ref_ptr<osg::Image> labelImage(const std::string& utf8)
{
    osgText::Font* font = labelFont();
    const osgText::FontResolution resolution(labelPixels, labelPixels);
    const double scale = labelPixels;  // glyph metrics are in units of the resolution
    struct Placed
    {
        osgText::Glyph* glyph;
        int x, y;  ///< lower left corner relative to the pen's start on the baseline
    };
    std::vector<Placed> placed;
    double pen = 0.0;
    int left = 0, right = 1, bottom = 0, top = 1;
    for (unsigned int code : osgText::String(utf8, osgText::String::ENCODING_UTF8)) {
        osgText::Glyph* glyph = font->getGlyph(resolution, code);
        if (!glyph && code == 0xB5) glyph = font->getGlyph(resolution, 'u');  // MICRO SIGN
        if (!glyph) continue;
        const int x = int(std::lround(pen + glyph->getHorizontalBearing().x() * scale));
        const int y = int(std::lround(glyph->getHorizontalBearing().y() * scale));
        placed.push_back({glyph, x, y});
        left = std::min(left, x), right = std::max(right, x + glyph->s());
        bottom = std::min(bottom, y), top = std::max(top, y + glyph->t());
        pen += glyph->getHorizontalAdvance() * scale;
    }
    right = std::max(right, int(std::ceil(pen)));
    const int width = right - left, height = top - bottom;
    osg::ref_ptr<osg::Image> image = new osg::Image;
    image->allocateImage(width, height, 1, GL_RED, GL_UNSIGNED_BYTE);
    image->setInternalTextureFormat(GL_R8);
    std::fill(image->data(), image->data() + image->getTotalSizeInBytes(), 0);
    for (const Placed& p : placed) {
        const osgText::Glyph& g = *p.glyph;
        const unsigned int step = g.getPixelSizeInBits() / 8, alpha = step - 1;  // GL_ALPHA, LUMINANCE_ALPHA or RGBA: coverage last
        for (int gy = 0; gy < g.t(); ++gy)
            for (int gx = 0; gx < g.s(); ++gx) {
                unsigned char& out = *image->data(p.x - left + gx, p.y - bottom + gy);
                out = std::max(out, g.data(gx, gy)[alpha]);
            }
    }
    return image;
}

/// A label quad drawn by `program` in `colour`.
Label makeLabel(osg::Program* program, osg::Uniform* colour)
{
    Label label;
    label.quad = new osg::Geometry;
    osg::Geometry& g = *label.quad;
    g.setDataVariance(osg::Object::DYNAMIC);
    g.setUseDisplayList(false);
    g.setUseVertexBufferObjects(true);
    g.setUseVertexArrayObject(true);
    g.setVertexArray(new osg::Vec3Array(4));
    g.addPrimitiveSet(new osg::DrawArrays(GL_TRIANGLE_STRIP, 0, 4));
    g.setDrawCallback(new MatrixUniforms);
    g.setCullingActive(false);
    label.texture->setFilter(osg::Texture::MIN_FILTER, osg::Texture::NEAREST);
    label.texture->setFilter(osg::Texture::MAG_FILTER, osg::Texture::NEAREST);
    label.texture->setWrap(osg::Texture::WRAP_S, osg::Texture::CLAMP_TO_EDGE);
    label.texture->setWrap(osg::Texture::WRAP_T, osg::Texture::CLAMP_TO_EDGE);
    label.texture->setResizeNonPowerOfTwoHint(false);
    label.texture->setDataVariance(osg::Object::DYNAMIC);
    osg::StateSet* ss = g.getOrCreateStateSet();
    ss->setAttributeAndModes(program);
    ss->setTextureAttribute(0, label.texture.get());
    ss->addUniform(new osg::Uniform("volren_labelTexture", 0));
    ss->addUniform(colour);
    ss->addUniform(label.origin.get());
    ss->addUniform(label.size.get());
    ss->setAttributeAndModes(new osg::BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA));
    return label;
}

/// Shows `text` in `label` with its image's anchor (fractions of its size: 0.5, 0 = centre of
/// the bottom edge) at `at`, on whole pixels.
void placeLabel(Label& label, const std::string& text, const osg::Vec2d& at, const osg::Vec2d& anchor)
{
    if (text != label.text || !label.texture->getImage()) {
        label.texture->setImage(labelImage(text).get());
        label.text = text;
    }
    const osg::Image& image = *label.texture->getImage();
    const osg::Vec2 size(float(image.s()), float(image.t()));
    const osg::Vec2 corner(float(std::round(at.x() - anchor.x() * size.x())), float(std::round(at.y() - anchor.y() * size.y())));
    auto* v = static_cast<osg::Vec3Array*>(label.quad->getVertexArray());
    (*v)[0].set(corner.x(), corner.y(), 0.0f);
    (*v)[1].set(corner.x() + size.x(), corner.y(), 0.0f);
    (*v)[2].set(corner.x(), corner.y() + size.y(), 0.0f);
    (*v)[3].set(corner.x() + size.x(), corner.y() + size.y(), 0.0f);
    v->dirty();
    label.quad->dirtyBound();
    label.origin->set(corner);
    label.size->set(size);
}

/// A quad (triangle strip of 4 vertices) drawn by the annotation program in `colour`.
osg::ref_ptr<osg::Geometry> shape(osg::Program* program, osg::Uniform* colour)
{
    osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
    g->setDataVariance(osg::Object::DYNAMIC);
    g->setUseDisplayList(false);
    g->setUseVertexBufferObjects(true);  // core profiles draw from buffers only
    g->setUseVertexArrayObject(true);
    g->setVertexArray(new osg::Vec3Array(4));
    g->addPrimitiveSet(new osg::DrawArrays(GL_TRIANGLE_STRIP, 0, 4));
    g->setDrawCallback(new MatrixUniforms);
    g->setCullingActive(false);
    osg::StateSet* ss = g->getOrCreateStateSet();
    ss->setAttributeAndModes(program);
    ss->addUniform(colour);
    return g;
}

/// Sets `g`'s quad to the segment from `a` to `b` (pixels) `width` wide; a dot where they meet.
void setSegment(osg::Geometry& g, const osg::Vec2d& a, const osg::Vec2d& b, double width)
{
    osg::Vec2d along = b - a;
    const double length = along.length();
    along = length > 1e-6 ? along / length : osg::Vec2d(1.0, 0.0);
    osg::Vec2d side(-along.y(), along.x());
    side *= 0.5 * width;
    const osg::Vec2d from = length > 1e-6 ? a : a - along * (0.5 * width);
    const osg::Vec2d to = length > 1e-6 ? b : a + along * (0.5 * width);
    auto* v = static_cast<osg::Vec3Array*>(g.getVertexArray());
    (*v)[0].set(osg::Vec3(from - side, 0.0f));
    (*v)[1].set(osg::Vec3(to - side, 0.0f));
    (*v)[2].set(osg::Vec3(from + side, 0.0f));
    (*v)[3].set(osg::Vec3(to + side, 0.0f));
    v->dirty();
    g.dirtyBound();
}

}  // namespace

Annotations::Annotations() : _parts(std::make_shared<Parts>())
{
    setName("volren annotations");
    osg::StateSet* ss = getOrCreateStateSet();
    ss->setRenderBinDetails(1000, "RenderBin");  // after the volumes (bin 10); never opaque geometry
    ss->setMode(GL_DEPTH_TEST, osg::StateAttribute::OFF | osg::StateAttribute::OVERRIDE);
    ss->setAttributeAndModes(new osg::Depth(osg::Depth::ALWAYS, 0.0, 1.0, false));

    _hud = new osg::Camera;
    _hud->setReferenceFrame(osg::Transform::ABSOLUTE_RF);
    _hud->setRenderOrder(osg::Camera::NESTED_RENDER);
    _hud->setClearMask(0);
    _hud->setAllowEventFocus(false);
    _hud->setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
    _hud->setViewMatrix(osg::Matrixd::identity());
    _hud->setCullingActive(false);
    addChild(_hud.get());

    const ShaderFunctionRegistry& registry = ShaderFunctionRegistry::instance();
    osg::ref_ptr<osg::Program> program = new osg::Program;
    program->setName("volren annotations");
    program->addShader(new osg::Shader(osg::Shader::VERTEX, registry.read("Overlay/annotation.vert")));
    program->addShader(new osg::Shader(osg::Shader::FRAGMENT, registry.read("Overlay/annotation.frag")));
    osg::ref_ptr<osg::Program> labels = new osg::Program;
    labels->setName("volren annotation labels");
    labels->addShader(new osg::Shader(osg::Shader::VERTEX, registry.read("Overlay/label.vert")));
    labels->addShader(new osg::Shader(osg::Shader::FRAGMENT, registry.read("Overlay/label.frag")));
    Parts& p = *_parts;
    p.geode->setCullingActive(false);
    p.bar = shape(program.get(), p.colour.get());
    p.label = makeLabel(labels.get(), p.colour.get());
    p.geode->addDrawable(p.bar.get());
    p.geode->addDrawable(p.label.quad.get());
    const std::array<osg::Vec4, 3> axisColours = {osg::Vec4(0.95f, 0.25f, 0.2f, 1.0f), osg::Vec4(0.3f, 0.85f, 0.3f, 1.0f),
                                                  osg::Vec4(0.3f, 0.5f, 1.0f, 1.0f)};
    for (int i = 0; i < 3; ++i) {
        osg::ref_ptr<osg::Uniform> colour = new osg::Uniform("volren_annotationColour", axisColours[i]);
        p.axes[i] = shape(program.get(), colour.get());
        p.axisNames[i] = makeLabel(labels.get(), colour.get());
        p.geode->addDrawable(p.axes[i].get());
        p.geode->addDrawable(p.axisNames[i].quad.get());
    }
    _hud->addChild(p.geode.get());
    setScaleBar(false);
    setAxes(false);
}

void Annotations::setScaleBar(bool on)
{
    _scaleBar = on;
    _parts->bar->setNodeMask(on ? ~0u : 0u);
    _parts->label.quad->setNodeMask(on ? ~0u : 0u);
}

void Annotations::setAxes(bool on)
{
    _axes = on;
    for (int i = 0; i < 3; ++i) {
        _parts->axes[i]->setNodeMask(on ? ~0u : 0u);
        _parts->axisNames[i].quad->setNodeMask(on ? ~0u : 0u);
    }
}

void Annotations::setColour(const osg::Vec4& colour)
{
    _parts->colour->set(colour);
}

ScaleBar Annotations::shownScaleBar() const
{
    std::lock_guard<std::mutex> lock(_mutex);
    return _shown;
}

std::string Annotations::shownLabel() const
{
    std::lock_guard<std::mutex> lock(_mutex);
    return _label;
}

void Annotations::traverse(osg::NodeVisitor& nv)
{
    if (auto* cv = dynamic_cast<osgUtil::CullVisitor*>(&nv); cv && cv->getCurrentCamera() && cv->getViewport()) {
        osg::BoundingSphere scene;  // the scene's bound without these annotations
        for (unsigned int i = 0; i < getNumParents(); ++i) scene.expandBy(getParent(i)->getBound());
        update(cv->getCurrentCamera()->getViewMatrix(), *cv->getProjectionMatrix(), *cv->getViewport(),
               scene.valid() ? osg::Vec3d(scene.center()) : osg::Vec3d());
    }
    osg::Group::traverse(nv);
}

void Annotations::update(const osg::Matrixd& view, const osg::Matrixd& projection, const osg::Viewport& viewport,
                         const osg::Vec3d& centre)
{
    const double w = viewport.width(), h = viewport.height();
    _hud->setProjectionMatrixAsOrtho2D(0.0, w, 0.0, h);
    Parts& p = *_parts;
    ScaleBar bar;
    std::string label;
    if (_scaleBar) {
        bar = scaleBarFor(view, projection, w, centre, 0.2 * w);
        const double right = w - barMargin, left = right - bar.pixels;
        setSegment(*p.bar, osg::Vec2d(left, barMargin + 0.5 * barThickness), osg::Vec2d(right, barMargin + 0.5 * barThickness),
                   bar.length > 0.0 ? barThickness : 0.0);
        label = bar.length > 0.0 ? lengthLabel(bar.length, _unit) : std::string();
        placeLabel(p.label, label, osg::Vec2d(0.5 * (left + right), barMargin + barThickness + 4.0), osg::Vec2d(0.5, 0.0));
    }
    if (_axes) {
        const osg::Vec2d origin(_leftMargin + gizmoOffset, gizmoOffset);
        for (int i = 0; i < 3; ++i) {
            osg::Vec3d axis;
            axis[i] = 1.0;
            const osg::Vec3d seen = osg::Matrixd::transform3x3(axis, view);  // eye coordinates
            const osg::Vec2d tip = origin + osg::Vec2d(seen.x(), seen.y()) * gizmoLength;
            setSegment(*p.axes[i], origin, tip, 3.0);
            osg::Vec2d away(seen.x(), seen.y());
            const double length = away.length();
            away = length > 0.2 ? away / length : osg::Vec2d(0.7, 0.7);
            const osg::Vec2d at = tip + away * 9.0;
            placeLabel(p.axisNames[i], std::string(1, char('x' + i)), at, osg::Vec2d(0.5, 0.5));
        }
    }
    std::lock_guard<std::mutex> lock(_mutex);
    _shown = bar;
    _label = label;
}

}  // namespace volren
