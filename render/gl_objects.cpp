#include "render/gl_objects.h"

#include <initializer_list>
#include <stdexcept>
#include <vector>

namespace physdbg::render {

namespace detail {
void deleteBuffer(GLuint name) { glDeleteBuffers(1, &name); }
void deleteVertexArray(GLuint name) { glDeleteVertexArrays(1, &name); }
void deleteProgram(GLuint name) { glDeleteProgram(name); }
void deleteFramebuffer(GLuint name) { glDeleteFramebuffers(1, &name); }
void deleteRenderbuffer(GLuint name) { glDeleteRenderbuffers(1, &name); }
void deleteTexture(GLuint name) { glDeleteTextures(1, &name); }
}  // namespace detail

namespace {

GLuint generateName(void (*generate)(GLsizei, GLuint*)) {
  GLuint name = 0;
  generate(1, &name);
  return name;
}

}  // namespace

GlBuffer createBuffer() { return GlBuffer(generateName(glGenBuffers)); }
GlVertexArray createVertexArray() { return GlVertexArray(generateName(glGenVertexArrays)); }
GlFramebuffer createFramebuffer() { return GlFramebuffer(generateName(glGenFramebuffers)); }
GlRenderbuffer createRenderbuffer() { return GlRenderbuffer(generateName(glGenRenderbuffers)); }
GlTexture createTexture() { return GlTexture(generateName(glGenTextures)); }

namespace {

// Owns a shader object only until it is linked into the program.
class ShaderObject {
 public:
  ShaderObject(GLenum type, const char* source, const std::string& label) : name_(glCreateShader(type)) {
    glShaderSource(name_, 1, &source, nullptr);
    glCompileShader(name_);
    GLint ok = 0;
    glGetShaderiv(name_, GL_COMPILE_STATUS, &ok);
    if (!ok) {
      std::vector<char> log(4096);
      glGetShaderInfoLog(name_, static_cast<GLsizei>(log.size()), nullptr, log.data());
      glDeleteShader(name_);
      throw std::runtime_error("shader '" + label + "' does not compile: " + log.data());
    }
  }
  ~ShaderObject() { glDeleteShader(name_); }
  ShaderObject(const ShaderObject&) = delete;
  ShaderObject& operator=(const ShaderObject&) = delete;
  GLuint get() const { return name_; }

 private:
  GLuint name_;
};

// Links the attached shaders; throws with the info log when they do not link.
GlProgram linkProgram(std::initializer_list<const ShaderObject*> shaders, const std::string& label) {
  GlProgram program(glCreateProgram());
  for (const ShaderObject* shader : shaders) glAttachShader(program.get(), shader->get());
  glLinkProgram(program.get());
  GLint ok = 0;
  glGetProgramiv(program.get(), GL_LINK_STATUS, &ok);
  if (!ok) {
    std::vector<char> log(4096);
    glGetProgramInfoLog(program.get(), static_cast<GLsizei>(log.size()), nullptr, log.data());
    throw std::runtime_error("program '" + label + "' does not link: " + log.data());
  }
  return program;
}

}  // namespace

GlProgram createProgram(const char* vertexSource, const char* fragmentSource, const std::string& label) {
  ShaderObject vertex(GL_VERTEX_SHADER, vertexSource, label + " (vertex)");
  ShaderObject fragment(GL_FRAGMENT_SHADER, fragmentSource, label + " (fragment)");
  return linkProgram({&vertex, &fragment}, label);
}

GlProgram createComputeProgram(const char* source, const std::string& label) {
  ShaderObject compute(GL_COMPUTE_SHADER, source, label + " (compute)");
  return linkProgram({&compute}, label);
}

void checkGlError(const char* what) {
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR) throw std::runtime_error(std::string("GL error ") + std::to_string(error) + " in " + what);
}

}  // namespace physdbg::render
