// PNG writer: the picture of a mesh (io/picture.h) rasterized with a depth buffer and
// supersampling (io/picture_raster.h), its colours limited to 256 so that the file is an
// indexed one, encoded by libpng; Print.Width x Print.Height pixels (else
// General.GraphicsWidth x General.GraphicsHeight).
#include <ostream>
#include <stdexcept>
#include <string>

#include "io/formats.h"
#include "io/picture.h"
#include "io/picture_raster.h"
#include "io/rgb_image.h"

namespace geomesh {

namespace {

constexpr int kLargestSide = 16384;  // pixels: a picture is held in memory, samples and all

}  // namespace

void writePng(std::ostream& out, const Model& model, const Mesh& mesh,
              const MeshWriteOptions& options) {
  if (options.pictureWidth > kLargestSide || options.pictureHeight > kLargestSide)
    throw std::invalid_argument("png pictures are at most " + std::to_string(kLargestSide) +
                                " pixels wide and high, not " +
                                std::to_string(options.pictureWidth) + "x" +
                                std::to_string(options.pictureHeight));
  const Picture picture = composePicture(model, mesh, pictureOptionsOf(options), "png");
  RgbImage image = rasterizePicture(picture, defaultSupersampling(picture.width, picture.height));
  limitColors(image, 256);  // an indexed PNG: a third of the size of an RGB one or less
  const std::string bytes = encodePng(image);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

}  // namespace geomesh
