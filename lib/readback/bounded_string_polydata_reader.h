// SPDX-License-Identifier: Apache-2.0
// vtkXMLPolyDataReader whose string arrays take at most the values they were sized for.
// VTK 9.1 reads a string array 1024 characters at a time and stores every
// NUL-terminated string of the last block read, however many the array holds: a
// damaged file with more strings than tuples overflows the array (found by the
// vtp_reader fuzz target). Here each string is stored only while the array has room,
// and a file whose data ends before the declared strings do fails the read.
// Internal to lib/readback/vtp_reader.cpp. Includes VTK headers.
#pragma once

#include <vtkXMLPolyDataReader.h>

namespace strielad::vtp {

class BoundedStringPolyDataReader : public vtkXMLPolyDataReader {
 public:
  static BoundedStringPolyDataReader* New();
  vtkTypeMacro(BoundedStringPolyDataReader, vtkXMLPolyDataReader);

 protected:
  BoundedStringPolyDataReader() = default;

  int ReadArrayValues(vtkXMLDataElement* element, vtkIdType array_index, vtkAbstractArray* array,
                      vtkIdType start_index, vtkIdType values, FieldType type) override;
};

}  // namespace strielad::vtp
