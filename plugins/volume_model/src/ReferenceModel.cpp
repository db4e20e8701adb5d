#include <volume_model/DeclarationLoader.h>
#include <volume_model/ReferenceModel.h>

namespace volren {

ReferenceModelCatalog& ReferenceModelCatalog::instance()
{
    static ReferenceModelCatalog catalog;
    return catalog;
}

void ReferenceModelCatalog::declare(const std::string& slot, const std::string& name, const ReferenceModel& model)
{
    _models[{slot, name}] = model;
}

const ReferenceModel* ReferenceModelCatalog::find(const std::string& slot, const std::string& name) const
{
    loadDeclarations();
    auto it = _models.find({slot, name});
    return it == _models.end() ? nullptr : &it->second;
}

const std::map<std::pair<std::string, std::string>, ReferenceModel>& ReferenceModelCatalog::all() const
{
    loadDeclarations();
    return _models;
}

}  // namespace volren
