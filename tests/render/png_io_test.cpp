// PNG files: exact round trips, clear errors naming the file, and hostile
// input (truncation at every byte, huge declared sizes, byte flips, every
// colour type and bit depth, interlacing).
#include <gtest/gtest.h>
#include <png.h>
#include <unistd.h>

#include <csetjmp>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>

#include "render/image.h"

namespace physdbg::render {
namespace {

Image randomImage(int width, int height, unsigned seed) {
  std::mt19937 generator(seed);
  std::uniform_int_distribution<int> byte(0, 255);
  Image image{width, height, std::vector<std::uint8_t>(static_cast<std::size_t>(width) * height * 4)};
  for (auto& value : image.rgba) value = static_cast<std::uint8_t>(byte(generator));
  return image;
}

// Named after the test and the process: CTest runs tests side by side (and
// two checkouts may run theirs at once), and two tests writing one
// "bytes.png" read each other's half-written or removed file.
std::string temporaryPath(const std::string& name) {
  const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  return (std::filesystem::temp_directory_path() /
          ("physdbg_png_test_" + std::to_string(::getpid()) + "_" + test + "_" + name))
      .string();
}

TEST(PngIo, RoundTripIsExactAtEveryLevel) {
  const Image image = randomImage(37, 23, 7);  // odd sizes catch stride mistakes
  for (int level : {0, 1, 9}) {
    const std::string path = temporaryPath("roundtrip.png");
    writePng(path, image, level);
    const Image back = readPng(path);
    EXPECT_EQ(back.width, image.width);
    EXPECT_EQ(back.height, image.height);
    EXPECT_EQ(back.rgba, image.rgba) << "level " << level;
    std::filesystem::remove(path);
  }
}

TEST(PngIo, UnwritablePathThrowsNamingThePath) {
  const std::string path = "/nonexistent-directory-physdbg/picture.png";
  try {
    writePng(path, randomImage(4, 4, 1));
    FAIL() << "no exception";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
  }
}

// The encoder pool encodes in memory and writes the bytes in frame order:
// the same file writePng makes.
TEST(PngIo, EncodedBytesAreTheFileWritePngMakes) {
  const Image image = randomImage(64, 48, 3);
  const std::string path = temporaryPath("encoded.png");
  writePng(path, image);
  std::ifstream file(path, std::ios::binary);
  const std::vector<std::uint8_t> written{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
  EXPECT_EQ(encodePng(image), written);
  std::filesystem::remove(path);
}

TEST(PngIo, AFullDiskFailsTheWriteNamingThePath) {
  try {
    writePngBytes("/dev/full", encodePng(randomImage(64, 48, 3)));
    FAIL() << "no exception";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("'/dev/full'"), std::string::npos) << error.what();
  }
}

TEST(PngIo, MissingFileThrowsNamingThePath) {
  const std::string path = temporaryPath("does_not_exist.png");
  try {
    readPng(path);
    FAIL() << "no exception";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
  }
}

TEST(PngIo, InconsistentImageIsRejected) {
  Image image = randomImage(4, 4, 2);
  image.rgba.pop_back();
  EXPECT_THROW(writePng(temporaryPath("bad.png"), image), std::invalid_argument);
  EXPECT_THROW(writePng(temporaryPath("bad.png"), Image{}), std::invalid_argument);
  EXPECT_THROW(writePng(temporaryPath("bad.png"), randomImage(2, 2, 3), 10), std::invalid_argument);
}

std::string fileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

std::string pngBytes(const Image& image) {
  const std::string path = temporaryPath("bytes.png");
  writePng(path, image);
  std::string bytes = fileBytes(path);
  std::filesystem::remove(path);
  return bytes;
}

// The image, or nothing after a std::runtime_error naming `name`; any other
// exception fails the test.
std::optional<Image> decodeOrNameTheFile(const std::string& bytes, const std::string& name) {
  try {
    return readPngBytes(bytes, name);
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("'" + name + "'"), std::string::npos) << error.what();
    return std::nullopt;
  }
}

TEST(PngIo, BytesInMemoryDecodeLikeTheFile) {
  const Image image = randomImage(13, 9, 4);
  const Image back = readPngBytes(pngBytes(image), "memory.png");
  EXPECT_EQ(back.width, 13);
  EXPECT_EQ(back.height, 9);
  EXPECT_EQ(back.rgba, image.rgba);
}

// A cut inside the closing IEND chunk loses no pixels and still decodes; any
// earlier cut is refused.
TEST(PngIo, TruncationAtEveryByteIsRefusedOrLosesNoPixels) {
  const Image image = randomImage(7, 5, 11);
  const std::string bytes = pngBytes(image);
  const std::size_t iendBytes = 12;
  for (std::size_t length = 0; length < bytes.size(); ++length) {
    const std::optional<Image> decoded = decodeOrNameTheFile(bytes.substr(0, length), "cut.png");
    EXPECT_EQ(decoded.has_value(), length >= bytes.size() - iendBytes) << "prefix of " << length << " bytes";
    if (decoded) {
      EXPECT_EQ(decoded->rgba, image.rgba) << "prefix of " << length << " bytes";
    }
  }
  const std::string path = temporaryPath("cut.png");
  std::ofstream(path, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  try {
    readPng(path);
    ADD_FAILURE() << "accepted";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
  }
  std::filesystem::remove(path);
}

TEST(PngIo, RandomByteFlipsDecodeOrAreRefused) {
  const std::string bytes = pngBytes(randomImage(7, 5, 12));
  std::mt19937 random(99);
  std::uniform_int_distribution<std::size_t> position(0, bytes.size() - 1);
  std::uniform_int_distribution<int> byte(0, 255);
  int refused = 0;
  for (int trial = 0; trial < 1000; ++trial) {
    std::string flipped = bytes;
    flipped[position(random)] = static_cast<char>(byte(random));
    refused += decodeOrNameTheFile(flipped, "flipped.png") ? 0 : 1;
  }
  EXPECT_GT(refused, 500);  // CRCs catch most flips
}

std::string bigEndian(std::uint32_t value) {
  return {static_cast<char>(value >> 24), static_cast<char>(value >> 16), static_cast<char>(value >> 8),
          static_cast<char>(value)};
}

std::uint32_t crc32Of(const std::string& bytes) {
  std::uint32_t crc = 0xffffffffu;
  for (const char byte : bytes) {
    crc ^= static_cast<std::uint8_t>(byte);
    for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

std::string pngChunk(const std::string& type, const std::string& data) {
  return bigEndian(static_cast<std::uint32_t>(data.size())) + type + data + bigEndian(crc32Of(type + data));
}

// A well-formed header (valid CRCs) declaring the size, then a token IDAT.
std::string declaredSizePng(std::uint32_t width, std::uint32_t height) {
  const std::string header = bigEndian(width) + bigEndian(height) + std::string("\x08\x06\x00\x00\x00", 5);
  return std::string("\x89PNG\r\n\x1a\n", 8) + pngChunk("IHDR", header) + pngChunk("IDAT", "\x78\x9c") +
         pngChunk("IEND", "");
}

TEST(PngIo, HugeDeclaredSizesAreRefusedBeforeAllocating) {
  ASSERT_EQ(crc32Of("IEND"), 0xae426082u);  // the CRC every PNG ends with
  for (const auto& [width, height] : std::vector<std::pair<std::uint32_t, std::uint32_t>>{
           {100000, 100000}, {maxImageSide + 1, 1}, {1, maxImageSide + 1}, {11586, 11586}, {0x7fffffff, 1}}) {
    const std::string name = "huge-" + std::to_string(width) + "x" + std::to_string(height) + ".png";
    EXPECT_FALSE(decodeOrNameTheFile(declaredSizePng(width, height), name));  // bad_alloc would escape
  }
  try {
    readPngBytes(declaredSizePng(100000, 100000), "huge.png");
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("100000x100000 pixels is over the limit"), std::string::npos)
        << error.what();
  }
}

// A PNG in a format physdbg never writes, made with libpng's full API.
struct PngSpec {
  int width = 0, height = 0, bitDepth = 8, colorType = PNG_COLOR_TYPE_RGB;
  bool interlaced = false;
  std::vector<std::uint8_t> rows;  // packed samples (16-bit ones big-endian), rows top to bottom
  std::vector<png_color> palette;
};

void appendToString(png_structp png, png_bytep data, png_size_t length) {
  static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(data), length);
}

void stopWriting(png_structp png, png_const_charp) { png_longjmp(png, 1); }

// The longjmp target owns nothing; encodeSpec frees the libpng structs.
bool writeSpec(png_structp png, png_infop info, const PngSpec& spec, png_bytep* rows, std::string* out) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_write_fn(png, out, appendToString, nullptr);
  png_set_IHDR(png, info, static_cast<png_uint_32>(spec.width), static_cast<png_uint_32>(spec.height), spec.bitDepth,
               spec.colorType, spec.interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_BASE, PNG_FILTER_TYPE_BASE);
  if (!spec.palette.empty()) png_set_PLTE(png, info, spec.palette.data(), static_cast<int>(spec.palette.size()));
  png_write_info(png, info);
  if (spec.interlaced) png_set_interlace_handling(png);
  png_write_image(png, rows);
  png_write_end(png, info);
  return true;
}

std::string encodeSpec(const PngSpec& spec) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, stopWriting, nullptr);
  png_infop info = png_create_info_struct(png);
  const std::size_t stride = spec.rows.size() / static_cast<std::size_t>(spec.height);
  std::vector<png_bytep> rows;
  for (int y = 0; y < spec.height; ++y) rows.push_back(const_cast<png_bytep>(spec.rows.data() + y * stride));
  std::string bytes;
  const bool written = writeSpec(png, info, spec, rows.data(), &bytes);
  png_destroy_write_struct(&png, &info);
  EXPECT_TRUE(written);
  return bytes;
}

struct FormatCase {
  std::string name;
  PngSpec spec;
  std::vector<std::uint8_t> expectedRgba;
  int tolerance = 0;  // levels; 16-bit samples are rounded to 8 bits
};

std::vector<FormatCase> formatCases() {
  std::vector<FormatCase> cases;
  cases.push_back({"grey 8", {3, 2, 8, PNG_COLOR_TYPE_GRAY, false, {0, 50, 100, 150, 200, 255}, {}},
                   {0, 0, 0, 255, 50, 50, 50, 255, 100, 100, 100, 255, 150, 150, 150, 255, 200, 200, 200, 255,
                    255, 255, 255, 255}});
  cases.push_back({"grey 16", {2, 1, 16, PNG_COLOR_TYPE_GRAY, false, {0x80, 0x80, 0x12, 0x12}, {}},
                   {0x80, 0x80, 0x80, 255, 0x12, 0x12, 0x12, 255}, 1});
  cases.push_back({"grey 1", {8, 1, 1, PNG_COLOR_TYPE_GRAY, false, {0xb2}, {}}, {}});
  for (const std::uint8_t bit : {1, 0, 1, 1, 0, 0, 1, 0})
    cases.back().expectedRgba.insert(cases.back().expectedRgba.end(), {std::uint8_t(bit * 255), std::uint8_t(bit * 255),
                                                                        std::uint8_t(bit * 255), 255});
  cases.push_back({"grey+alpha 8", {2, 1, 8, PNG_COLOR_TYPE_GRAY_ALPHA, false, {90, 255, 200, 128}, {}},
                   {90, 90, 90, 255, 200, 200, 200, 128}, 1});
  cases.push_back({"palette 8", {3, 1, 8, PNG_COLOR_TYPE_PALETTE, false, {2, 0, 1}, {{10, 20, 30}, {40, 50, 60}, {70, 80, 90}}},
                   {70, 80, 90, 255, 10, 20, 30, 255, 40, 50, 60, 255}});
  cases.push_back({"rgb 16", {1, 1, 16, PNG_COLOR_TYPE_RGB, false, {0x10, 0x10, 0xf0, 0xf0, 0x77, 0x77}, {}},
                   {0x10, 0xf0, 0x77, 255}, 1});
  cases.push_back({"rgba 16", {1, 1, 16, PNG_COLOR_TYPE_RGB_ALPHA, false, {0x10, 0x10, 0xf0, 0xf0, 0x77, 0x77, 0xff, 0xff}, {}},
                   {0x10, 0xf0, 0x77, 255}, 1});
  std::mt19937 random(5);
  FormatCase interlaced{"rgb 8 interlaced", {9, 7, 8, PNG_COLOR_TYPE_RGB, true, {}, {}}, {}};
  for (int i = 0; i < 9 * 7; ++i) {
    const std::uint8_t r = random() & 255, g = random() & 255, b = random() & 255;
    interlaced.spec.rows.insert(interlaced.spec.rows.end(), {r, g, b});
    interlaced.expectedRgba.insert(interlaced.expectedRgba.end(), {r, g, b, 255});
  }
  cases.push_back(interlaced);
  return cases;
}

TEST(PngIo, EveryColourTypeAndBitDepthIsConvertedToRgba) {
  for (const FormatCase& format : formatCases()) {
    SCOPED_TRACE(format.name);
    const Image image = readPngBytes(encodeSpec(format.spec), format.name);
    ASSERT_EQ(image.width, format.spec.width);
    ASSERT_EQ(image.height, format.spec.height);
    ASSERT_EQ(image.rgba.size(), format.expectedRgba.size());
    for (std::size_t i = 0; i < image.rgba.size(); ++i)
      EXPECT_NEAR(image.rgba[i], format.expectedRgba[i], format.tolerance) << "byte " << i;
  }
}

}  // namespace
}  // namespace physdbg::render
