// The time scheme of this verification binary (tests/CMakeLists.txt links the suite once per scheme).
namespace qs::test {
const char* defaultTestScheme() { return "explicit"; }
}  // namespace qs::test
