// What `mirage compare` measures of each frame beyond the whole-image figures: the error per
// reflector and per cause (the ray tracer's first hits, eval/causes.h), and how far the matched
// reference is from a converged one (--reference-check). Shared by one view and by paths.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "app/compare_common.h"
#include "eval/causes.h"

namespace mirage::app {

// The reference side of one frame, at the output size.
struct ReferenceFrame {
  Image display;  // after the display transform
  IdImage mask;   // reflector ids (majority of the sub-pixels under --ssaa)
  std::optional<PixelCauses> causes;
};

// Unique display names of the scene's reflectors, in reflector-id order (an instance's name, with
// its id added where it is empty or repeated).
std::vector<std::string> reflectorNames(const Scene& scene);
// A diffuse instance's name as the per-object figures give it ("instance N" when it has none).
std::string objectName(const Scene& scene, int instance);
// Each diffuse instance's layer ("environment" or "object") by objectName.
std::map<std::string, std::string> objectLayers(const Scene& scene, const SceneLayers& layers);

// The causes of the reference's reflector pixels: the run's ray tracer at `time`, through the
// frame's sub-pixels (`frame_view`: the supersampled view).
PixelCauses traceCauses(CompareRun& run, const View& frame_view, float time, const IdImage& mask);

// A method's figures against the reference: the whole-image metrics (returned), the regions and
// the FLIP map for the report.
ImageMetrics analyseFrame(const CompareRun& run, const Image& shown,
                          const ReferenceFrame& reference, RegionSet& regions,
                          Image2D<float>* flip);

// Renders the converged reference (`spp` stratified samples a pixel at the output size) and
// fills run.report.reference_info with the matched reference's distance from it.
void checkReference(CompareRun& run, const View& output_view, float time,
                    const ReferenceFrame& reference, int spp);

}  // namespace mirage::app
