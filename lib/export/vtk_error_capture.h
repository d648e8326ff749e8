// SPDX-License-Identifier: Apache-2.0
// Internal to the library's VTK translation units (lib/export/vtp_*.cpp,
// lib/peers/vtk_paper_pipeline.cpp): collects the errors VTK objects report, instead of
// letting vtkOutputWindow print them, so that they become strielad::Error.
// Includes VTK headers: never include it from a public header.
#pragma once

#include <vtkAlgorithm.h>
#include <vtkCommand.h>
#include <vtkExecutive.h>
#include <vtkObject.h>

#include <string>

namespace strielad::vtk_support {

class ErrorCapture : public vtkCommand {
 public:
  static ErrorCapture* New() { return new ErrorCapture; }

  // Observes ErrorEvent and WarningEvent of `object` (warnings are dropped: VTK 9.1 warns
  // about empty inputs, which are normal here).
  void watch(vtkObject* object) {
    object->AddObserver(vtkCommand::ErrorEvent, this);
    object->AddObserver(vtkCommand::WarningEvent, this);
  }

  // An algorithm and its executive (which reports failed pipeline requests).
  void watch(vtkAlgorithm* algorithm) {
    watch(static_cast<vtkObject*>(algorithm));
    watch(static_cast<vtkObject*>(algorithm->GetExecutive()));
  }

  void Execute(vtkObject* /*caller*/, unsigned long event, void* call_data) override {
    if (event != vtkCommand::ErrorEvent) return;
    std::string text = call_data != nullptr ? static_cast<const char*>(call_data) : "unknown error";
    for (char& c : text) {
      if (c == '\n') c = ' ';
    }
    while (!text.empty() && text.back() == ' ') text.pop_back();
    if (!message_.empty()) message_ += "; ";
    message_ += text;
  }

  bool failed() const { return !message_.empty(); }
  const std::string& message() const { return message_; }
  void clear() { message_.clear(); }

 private:
  std::string message_;
};

}  // namespace strielad::vtk_support
