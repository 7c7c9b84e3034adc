// geometry/pattern/role.h: guessing a piece's role (front, back, sleeve, ...) from its name.
#pragma once

#include <string>
#include <string_view>

namespace tp::geometry {

/// The role a piece name suggests, for placing it on the body when no placement is given:
/// "sleeve", "hood", "collar", "cuff", "waistband", "pocket", "front", "back", or "" when the name
/// says nothing. Case-insensitive; understands compounds like "frontSideDart", "left_ftorso",
/// "skirt_back", "pant_f_r", "Back Bodice".
std::string guess_role(std::string_view piece_name);

}  // namespace tp::geometry
