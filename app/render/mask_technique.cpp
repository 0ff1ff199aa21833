#include "app/render/mask_technique.hpp"

#include "app/render/reference_mask.hpp"
#include "app/render/volume_mask.hpp"

namespace ecoview {

std::unique_ptr<MaskTechnique> make_mask_technique(shadow::Method method, const MaskSources& sources) {
  switch (method) {
    case shadow::Method::volumes: return std::make_unique<VolumeMask>(VolumeMask::Where::everywhere, sources);
    case shadow::Method::hybrid: return std::make_unique<VolumeMask>(VolumeMask::Where::near_map_edges, sources);
    case shadow::Method::reference: return std::make_unique<ReferenceMask>(sources);
    default: return nullptr;
  }
}

}  // namespace ecoview
