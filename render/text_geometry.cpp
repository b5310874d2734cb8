#include "render/text_geometry.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <stb/stb_easy_font.h>

namespace physdbg::render {
namespace {

constexpr debugdraw::Color kOutlineColor{0.0f, 0.0f, 0.0f, 0.85f};
constexpr std::size_t kMaxQuadsPerCharacter = 11;  // stb_easy_font's busiest glyph
constexpr std::size_t kVerticesPerQuad = 6;
constexpr std::size_t kPassesPerText = 9;  // eight outline offsets and the glyphs
constexpr float kLineHeight = 12;  // stb_easy_font's line pitch, in font units
constexpr float kBaseline = 7;     // bottom of a capital on the first line

struct Quad {
  float x0, y0, x1, y1;  // font units, y down
};

// stb_easy_font writes 4 vertices of 16 bytes (x, y, z floats, 4 colour bytes)
// per quad, on average ~270 bytes per character; 1 KiB per character is ample.
std::vector<Quad> glyphQuads(const std::string& text) {
  // The font covers printable ASCII only and indexes its table by character
  // code, so anything else (tabs, UTF-8 bytes) becomes '?' rather than a wild read.
  std::vector<char> characters;
  characters.reserve(text.size() + 1);
  for (char character : text)
    characters.push_back(character == '\n' || (character >= 32 && character <= 126) ? character : '?');
  characters.push_back('\0');
  std::vector<float> buffer((text.size() + 1) * 256);
  const int quadCount = stb_easy_font_print(0, 0, characters.data(), nullptr, buffer.data(),
                                            static_cast<int>(buffer.size() * sizeof(float)));
  std::vector<Quad> quads(static_cast<std::size_t>(quadCount));
  for (int index = 0; index < quadCount; ++index) {
    const float* corner = buffer.data() + static_cast<std::size_t>(index) * 16;  // 4 vertices x 4 words
    quads[index] = Quad{corner[0], corner[1], corner[8], corner[9]};           // first and third corner
  }
  return quads;
}

void validate(const debugdraw::Text& text) {
  if (text.text.size() > debugdraw::maxTextCharacters)
    throw std::invalid_argument("debug draw: text of " + std::to_string(text.text.size()) +
                                " characters, over the limit of " + std::to_string(debugdraw::maxTextCharacters));
  if (!(text.scale > 0) || !std::isfinite(text.scale))
    throw std::invalid_argument("debug draw: text scale must be positive, got " + std::to_string(text.scale));
  if (!std::isfinite(text.x) || !std::isfinite(text.y))
    throw std::invalid_argument("debug draw: text position is not finite");
}

void appendQuads(const debugdraw::Text& text, float offsetX, float offsetY, const debugdraw::Color& color,
                 std::vector<TextVertex>& triangles) {
  const float originX = std::round(text.x) + offsetX, originY = std::round(text.y) + offsetY;
  auto vertex = [&](float x, float y) {
    return TextVertex{{originX + std::round(x * text.scale), originY + std::round(y * text.scale)},
                      {color.r, color.g, color.b, color.a}};
  };
  const std::vector<Quad> quads = glyphQuads(text.text);
  if (triangles.size() + quads.size() * kVerticesPerQuad > maxTextVertices())
    throw std::invalid_argument("debug draw: a frame's text is over the limit of " +
                                std::to_string(debugdraw::maxFrameTextCharacters) + " characters");
  for (const Quad& quad : quads) {
    const TextVertex a = vertex(quad.x0, quad.y0), b = vertex(quad.x1, quad.y0);
    const TextVertex c = vertex(quad.x1, quad.y1), d = vertex(quad.x0, quad.y1);
    triangles.insert(triangles.end(), {a, b, c, a, c, d});
  }
}

// Right edge of the glyphs, in font units: what a label is centred by.
float inkWidth(const std::string& text) {
  float width = 0;
  for (const Quad& quad : glyphQuads(text)) width = std::max(width, quad.x1);
  return width;
}

}  // namespace

void validateLabel(const debugdraw::Label& label) {
  if (!label.position.allFinite()) throw std::invalid_argument("debug draw: label position is not finite");
  validate(debugdraw::Text{0, 0, label.scale, label.text, label.color, label.tag});
}

debugdraw::Text labelText(const debugdraw::Label& label, const Eigen::Vector2d& anchor) {
  validateLabel(label);
  const auto lines = static_cast<float>(std::count(label.text.begin(), label.text.end(), '\n'));
  const float baseline = (lines * kLineHeight + kBaseline) * label.scale;
  const float x = static_cast<float>(anchor.x()) - 0.5f * inkWidth(label.text) * label.scale;
  const float y = static_cast<float>(anchor.y()) - kLabelGapPixels - baseline;
  return debugdraw::Text{x, y, label.scale, label.text, label.color, label.tag};
}

std::array<float, 4> textExtent(const debugdraw::Text& text) {
  const auto lines = static_cast<float>(std::count(text.text.begin(), text.text.end(), '\n') + 1);
  const float margin = std::max(1.0f, std::round(text.scale * 0.5f));  // the outline's step
  return {text.x - margin, text.y - margin, text.x + inkWidth(text.text) * text.scale + margin,
          text.y + lines * kLineHeight * text.scale + margin};
}

std::size_t maxTextVertices() {
  return debugdraw::maxFrameTextCharacters * kMaxQuadsPerCharacter * kVerticesPerQuad * kPassesPerText;
}

void appendText(const debugdraw::Text& text, std::vector<TextVertex>& triangles) {
  validate(text);
  appendQuads(text, 0, 0, text.color, triangles);
}

void appendTextOutline(const debugdraw::Text& text, std::vector<TextVertex>& triangles) {
  validate(text);
  const float step = std::max(1.0f, std::round(text.scale * 0.5f));
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx)
      if (dx != 0 || dy != 0) appendQuads(text, dx * step, dy * step, kOutlineColor, triangles);
}

}  // namespace physdbg::render
