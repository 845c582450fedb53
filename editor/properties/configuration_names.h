#pragma once
// The render configurations as people read them ("Full"), where files and the command line use
// their identifiers ("full", renderer/configuration.h). The names are proper names (the docs and
// `glint bench` use them), marked for translation all the same.
#include <QString>
#include <QStringList>

#include <string_view>

namespace glint::editor {

// Every configuration's identifier, in the order the editor lists them.
const QStringList& configurationIds();
// The name shown for an identifier; an unknown identifier is shown as it is.
QString configurationTitle(std::string_view id);

} // namespace glint::editor
