#pragma once
#include <volume_model/ParameterDecl.h>

#include <deque>
#include <map>
#include <string>

namespace volren {

/// Every declared parameter of the shader-function implementations, in declaration order.
/// The model knows no implementation: the renderer's registry declares them here as it registers
/// its implementations, so that the model's settings, the panel and the serializers can read and
/// validate parameters without linking the renderer (a look-up loads them: DeclarationLoader.h).
class ParameterCatalog
{
public:
    /// The process-wide catalog.
    static ParameterCatalog& instance();

    /// Adds `decl`. The same parameter declared again by another implementation of its slot
    /// adds that implementation to its readers; any other use of a taken key or alias (another
    /// slot, another type, default or range) throws std::logic_error naming both declarations.
    /// Also throws for a default outside its own range or a panel span outside it.
    void declare(const ParameterDecl& decl);
    /// The declaration of `key` or of an alias (any case), or null.
    const ParameterDecl* find(const std::string& key) const;
    /// Every declaration, in declaration order.
    const std::deque<ParameterDecl>& all() const;

private:
    std::deque<ParameterDecl> _decls;
    std::map<std::string, std::size_t> _index;  ///< lower-case key or alias -> its declaration
};

}  // namespace volren
