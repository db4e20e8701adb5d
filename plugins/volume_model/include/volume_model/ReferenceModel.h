#pragma once
#include <map>
#include <string>
#include <utility>

namespace volren {

/// How the CPU reference renderer models one shader-function implementation, declared beside the
/// implementation's entry: the reference implements each named model itself (it shares no shader
/// code with the renderer) and selects it by this declaration. Plain data.
struct ReferenceModel
{
    enum class Fidelity
    {
        Exact,        ///< the implementation computes the model (to float precision)
        Approximate,  ///< it approximates the model within `bound`
        None,         ///< the reference has no model of it (`why`)
    };
    Fidelity fidelity = Fidelity::None;
    /// The reference's name of what it computes (volume_reference/README.md lists them), e.g.
    /// "blinn-phong" or "exact shadows".
    std::string model = {};
    /// Approximate: the largest difference from the model, per colour channel, that the
    /// implementation's tests hold it to.
    double bound = 0.0;
    std::string why = {};  ///< None: why there is no model

    /// Computed exactly (to float precision) by the reference as `model`.
    static ReferenceModel exact(std::string model) { return {Fidelity::Exact, std::move(model)}; }
    /// Approximates `model` within `bound`.
    static ReferenceModel approximate(std::string model, double bound)
    {
        return {Fidelity::Approximate, std::move(model), bound};
    }
    /// Not modelled, for the reason `why`.
    static ReferenceModel none(std::string why) { return {Fidelity::None, {}, 0.0, std::move(why)}; }
};

/// Every implementation's declared reference model, by slot and implementation name. The model
/// names no implementation: the renderer's registry declares them (DeclarationLoader.h).
class ReferenceModelCatalog
{
public:
    /// The process-wide catalog.
    static ReferenceModelCatalog& instance();
    /// Declares (or replaces) the model of implementation `name` of `slot`.
    void declare(const std::string& slot, const std::string& name, const ReferenceModel& model);
    /// The model of implementation `name` of `slot`, or null when it declares none.
    const ReferenceModel* find(const std::string& slot, const std::string& name) const;
    /// Every declaration: (slot, implementation) -> model.
    const std::map<std::pair<std::string, std::string>, ReferenceModel>& all() const;

private:
    std::map<std::pair<std::string, std::string>, ReferenceModel> _models;
};

}  // namespace volren
