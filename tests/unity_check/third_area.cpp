// A file-local name of its own: with second_area.cpp compiled alone, this file and first_area.cpp check clean.
namespace {
constexpr int kThirdSide = 2;
}  // namespace

int thirdArea() { return kThirdSide * kThirdSide; }
