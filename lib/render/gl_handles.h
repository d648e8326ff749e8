// SPDX-License-Identifier: Apache-2.0
// Owning handles of OpenGL objects: each deletes its object when it goes out of scope,
// moves but does not copy. The context that created the object must be current.
#pragma once

#include <epoxy/gl.h>

#include <utility>

namespace strielad::render {

template <void (*Delete)(GLuint)>
class GlHandle {
 public:
  GlHandle() = default;
  explicit GlHandle(GLuint id) : id_(id) {}
  ~GlHandle() { reset(); }
  GlHandle(GlHandle&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
  GlHandle& operator=(GlHandle&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, 0);
    }
    return *this;
  }
  GlHandle(const GlHandle&) = delete;
  GlHandle& operator=(const GlHandle&) = delete;

  GLuint get() const { return id_; }
  explicit operator bool() const { return id_ != 0; }
  void reset() {
    if (id_ != 0) Delete(id_);
    id_ = 0;
  }

 private:
  GLuint id_ = 0;
};

namespace detail {
inline void delete_buffer(GLuint id) { glDeleteBuffers(1, &id); }
inline void delete_vertex_array(GLuint id) { glDeleteVertexArrays(1, &id); }
inline void delete_texture(GLuint id) { glDeleteTextures(1, &id); }
inline void delete_framebuffer(GLuint id) { glDeleteFramebuffers(1, &id); }
inline void delete_program(GLuint id) { glDeleteProgram(id); }
inline void delete_shader(GLuint id) { glDeleteShader(id); }
inline void delete_query(GLuint id) { glDeleteQueries(1, &id); }
}  // namespace detail

using GlBuffer = GlHandle<detail::delete_buffer>;
using GlVertexArray = GlHandle<detail::delete_vertex_array>;
using GlTexture = GlHandle<detail::delete_texture>;
using GlFramebuffer = GlHandle<detail::delete_framebuffer>;
using GlProgram = GlHandle<detail::delete_program>;
using GlShader = GlHandle<detail::delete_shader>;
using GlQuery = GlHandle<detail::delete_query>;

inline GlBuffer make_buffer() {
  GLuint id = 0;
  glCreateBuffers(1, &id);
  return GlBuffer(id);
}
inline GlVertexArray make_vertex_array() {
  GLuint id = 0;
  glCreateVertexArrays(1, &id);
  return GlVertexArray(id);
}
inline GlTexture make_texture(GLenum target) {
  GLuint id = 0;
  glCreateTextures(target, 1, &id);
  return GlTexture(id);
}
inline GlFramebuffer make_framebuffer() {
  GLuint id = 0;
  glCreateFramebuffers(1, &id);
  return GlFramebuffer(id);
}
inline GlQuery make_query(GLenum target) {
  GLuint id = 0;
  glCreateQueries(target, 1, &id);
  return GlQuery(id);
}

}  // namespace strielad::render
