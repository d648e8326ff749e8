// SPDX-License-Identifier: Apache-2.0
#include "readback/bounded_string_polydata_reader.h"

#include <vtkObjectFactory.h>
#include <vtkStringArray.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>

#include <array>
#include <cstring>
#include <string>

namespace strielad::vtp {
namespace {

// Reads strings start_index .. start_index + values - 1 of the array element into `array`
// from index array_index on; 0 when the data ends first or the array has no room.
int read_strings(vtkXMLDataParser* parser, vtkXMLDataElement* element, vtkIdType array_index,
                 vtkStringArray* array, vtkIdType start_index, vtkIdType values) {
  const bool appended = element->GetAttribute("offset") != nullptr;
  vtkTypeInt64 offset = 0;
  if (appended && !element->GetScalarAttribute("offset", offset)) return 0;
  const char* format = element->GetAttribute("format");
  const int ascii = format != nullptr && std::strcmp(format, "binary") == 0 ? 0 : 1;
  const vtkIdType wanted = start_index + values;
  std::array<char, 1024> block{};
  std::string pending;
  vtkTypeUInt64 read = 0;
  vtkIdType in = 0;
  vtkIdType out = array_index;
  while (in < wanted) {
    const std::size_t n =
        appended ? parser->ReadAppendedData(offset, block.data(), read, block.size())
                 : parser->ReadInlineData(element, ascii, block.data(), read, block.size());
    if (n == 0 || n > block.size()) return 0;
    read += n;
    for (std::size_t i = 0; i < n && in < wanted; ++i) {
      if (block[i] != '\0') {
        pending.push_back(block[i]);
        continue;
      }
      if (in >= start_index) {
        if (out < 0 || out >= array->GetNumberOfValues()) return 0;
        array->SetValue(out++, pending);
      }
      ++in;
      pending.clear();
    }
  }
  return 1;
}

}  // namespace

vtkStandardNewMacro(BoundedStringPolyDataReader);

int BoundedStringPolyDataReader::ReadArrayValues(vtkXMLDataElement* element, vtkIdType array_index,
                                                 vtkAbstractArray* array, vtkIdType start_index,
                                                 vtkIdType values, FieldType type) {
  auto* strings = vtkStringArray::SafeDownCast(array);
  if (strings == nullptr) {
    return vtkXMLPolyDataReader::ReadArrayValues(element, array_index, array, start_index, values,
                                                 type);
  }
  if (this->AbortExecute) return 0;
  const int ok = read_strings(this->XMLParser, element, array_index, strings, start_index, values);
  strings->Modified();
  return ok;
}

}  // namespace strielad::vtp
