// rasterizePicture: a Picture into pixels, with a depth buffer and supersampling.
#pragma once

#include "io/picture.h"
#include "io/rgb_image.h"

namespace geomesh {

// Each face is filled where it is nearest, element edges drawn inside faces about one pixel
// wide across a shared edge; lines are strokes 1.2 pixels wide. Every pixel averages
// `supersampling` x `supersampling` samples (at least 1); the result depends on the picture
// alone.
RgbImage rasterizePicture(const Picture& picture, int supersampling);

// The supersampling rasterizePicture is given for a picture of this size: 2 (four samples a
// pixel) up to 4 megapixels, 1 above, so that large pictures stay fast.
int defaultSupersampling(int width, int height);

}  // namespace geomesh
