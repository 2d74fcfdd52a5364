"""asymptotics"""
