#include "towgeom/progress.hpp"

TOWGEOM_BEGIN_NAMESPACE

Progress::~Progress() = default;

void Progress::update(const std::string&, std::size_t, std::size_t) {}

TOWGEOM_END_NAMESPACE
