#include <volume_model/DeclarationLoader.h>
#include <volume_model/ParameterCatalog.h>

#include <stdexcept>

namespace volren {

ParameterCatalog& ParameterCatalog::instance()
{
    static ParameterCatalog catalog;
    return catalog;
}

namespace {

std::string describe(const ParameterDecl& d) { return "'" + d.key + "' of " + d.owners(); }

}  // namespace

void ParameterCatalog::declare(const ParameterDecl& decl)
{
    if (decl.key.empty() || decl.slot.empty())
        throw std::logic_error("a parameter needs a key and a slot (" + describe(decl) + ")");
    if (!decl.valid(decl.defaultValue))
        throw std::logic_error("parameter " + describe(decl) + ": its default " + decl.format(decl.defaultValue) +
                               " is not " + decl.range());
    const bool slider = decl.panel.kind == PanelHint::Slider || decl.panel.kind == PanelHint::LogSlider;
    if (slider && decl.panel.lo != decl.panel.hi &&
        (decl.panel.lo > decl.panel.hi || decl.panel.lo < decl.lo || decl.panel.hi > decl.hi ||
         (decl.openLow && decl.panel.lo <= decl.lo)))
        throw std::logic_error("parameter " + describe(decl) + ": its panel span is not within " + decl.range());
    if (decl.panel.kind == PanelHint::LogSlider && !(decl.panel.lo > 0.0))
        throw std::logic_error("parameter " + describe(decl) + ": a logarithmic slider needs a span above 0");
    if (auto it = _index.find(lowerKey(decl.key)); it != _index.end() && _decls[it->second].key == decl.key) {
        ParameterDecl& d = _decls[it->second];  // declared again: the same parameter, another reader
        if (!d.sameAs(decl))
            throw std::logic_error("parameter key clash: " + describe(decl) + " is declared differently by " +
                                   describe(d) + " (keys are unique across the registry: choose another)");
        for (const std::string& name : decl.implementations)
            if (!d.readBy(d.slot, name) && !d.implementations.empty()) d.implementations.push_back(name);
        if (decl.implementations.empty()) d.implementations.clear();
        return;
    }
    std::vector<std::string> names = decl.aliases;
    names.push_back(decl.key);
    for (const std::string& name : names)
        if (auto it = _index.find(lowerKey(name)); it != _index.end())
            throw std::logic_error("parameter key clash: '" + name + "' of " + describe(decl) + " is taken by " +
                                   describe(_decls[it->second]) + " (keys are unique across the registry: choose another)");
    for (const std::string& name : names) _index[lowerKey(name)] = _decls.size();
    _decls.push_back(decl);
}

const ParameterDecl* ParameterCatalog::find(const std::string& key) const
{
    loadDeclarations();
    auto it = _index.find(lowerKey(key));
    return it == _index.end() ? nullptr : &_decls[it->second];
}

const std::deque<ParameterDecl>& ParameterCatalog::all() const
{
    loadDeclarations();
    return _decls;
}

}  // namespace volren
