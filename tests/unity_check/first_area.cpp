// A file-local constant whose name second_area.cpp defines too: fine file by file, a redefinition in one unity source.
namespace {
constexpr int kSide = 4;
}  // namespace

int firstArea() { return kSide * kSide; }
