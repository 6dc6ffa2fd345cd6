from transforms3d import affines as affines, axangles as axangles, euler as euler, quaternions as quaternions, taitbryan as taitbryan
