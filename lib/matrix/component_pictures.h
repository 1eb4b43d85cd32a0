// dctimestep's image-based form (a DC or view spec with %d): one picture per bin (rcontrib -fc with -x and -y),
// summed with the bins' weights of one time step, as Radiance's dctimestep sums them.
#pragma once
#include <string>

#include "matrix/matrix.h"

namespace brume {

// Σ_b picture(b) × weights(b, step), each bin's picture named by `pattern` with b (printf's %d); a matrix of
// the pictures' rows and columns, RGB. Pictures of a zero weight are skipped, but the first. Throws Error:
// a picture that cannot be read, one of another size, a pattern with other conversions than one integer.
Matrix sumComponentPictures(const std::string& pattern, const Matrix& weights, int step);

// Whether a matrix spec names pictures by bin (holds a %d, %03d, …).
bool namesComponentPictures(const std::string& spec);

}  // namespace brume
