#include "boundary/wall.hpp"

#include <cmath>

namespace orogen {

double Wall::length() const { return std::hypot(bx - ax, by - ay); }

}  // namespace orogen
