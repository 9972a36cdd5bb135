#include "parallel/mpi_stepping.hpp"

namespace orogen {

MpiStepping::MpiStepping(World& world) : world_(world), step_(world, transport_) { world_.step_as_rank(this); }

MpiStepping::~MpiStepping() { world_.step_as_rank(nullptr); }  // the transport waits for its sends

}  // namespace orogen
