// See first_area.cpp.
namespace {
constexpr int kSide = 8;
}  // namespace

int secondArea() { return kSide * kSide; }
