// Line samples in image pixels for the rtsc agreement measures: "is a sample within r px of
// p?", answered by the product's spatial hash (geometry/point_grid.hpp) in the plane z = 0.
#pragma once
#include <glm/glm.hpp>

#include "geometry/point_grid.hpp"

namespace inkshade::test {

class ImagePointGrid {
public:
    explicit ImagePointGrid(double cell) : grid_(cell) {}
    void add(glm::dvec2 p) { grid_.add(glm::dvec3(p, 0.0)); }
    bool near(glm::dvec2 p, double r) const { return grid_.any_within(glm::dvec3(p, 0.0), r); }

private:
    geometry::PointGrid grid_;
};

}  // namespace inkshade::test
